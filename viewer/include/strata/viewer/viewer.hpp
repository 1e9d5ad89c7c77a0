#pragma once
#include <filesystem>
#include <string>

#include <strata/host/engine.hpp>
#include <strata/viewer/panel_overlay.hpp>
#include <strata/viewer/parameter_panel.hpp>
#include <strata/viewer/pipeline_watcher.hpp>
#include <strata/window/glfw_window.hpp>

namespace strata::viewer {

// The viewer (`strata view`, docs/viewer.md): the engine's pipeline in a window, navigated with the mouse
// and the keyboard (OrbitControls; Home goes back to the pipeline's camera), its parameters and its scene
// in panels over the frame, and loaded again when its file changes. On the window's GL thread.
class Viewer {
 public:
  Viewer(GlfwWindow& window, Engine& engine);

  // Takes the events since the last frame, draws one with the panels over it and shows it; returns the
  // engine's frame, or none while the window is minimised or the pipeline fails to render (a node's error,
  // shown in the panel until the pipeline's file changes and loads).
  const FrameOutput* frame();
  // What the parameter panel says is wrong: a refused change, a file that no longer loads, a failed frame.
  const std::string& problem() const { return panel_.reported(); }
  // Writes the view as it is now at width x height, whatever the window's size, through the engine's
  // headless path: every page loaded and the detail settled (Engine::renderSettled), then a PNG.
  void screenshot(const std::filesystem::path& file, int width, int height);

 private:
  void navigate();
  void reload();
  const FrameOutput* renderedFrame();

  GlfwWindow& window_;
  Engine& engine_;
  PanelOverlay overlay_;  // after the window's own input callbacks, which ImGui chains
  ParameterPanel panel_;
  PipelineWatcher watcher_;
  int width_ = 0;  // the window's framebuffer, pixels
  int height_ = 0;
  bool failed_ = false;  // the pipeline threw while rendering: not tried again until it loads anew
};

}  // namespace strata::viewer
