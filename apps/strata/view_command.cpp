#include <cstdio>
#include <memory>

#include <strata/engine.hpp>
#include <strata/error.hpp>
#include <strata/viewer/panel_overlay.hpp>
#include <strata/viewer/parameter_panel.hpp>
#include <strata/viewer/pipeline_watcher.hpp>
#include <strata/viewer/scene_panel.hpp>
#include <strata/window/glfw_window.hpp>

#include "command_options.hpp"
#include "commands.hpp"
#include "orbit_controls.hpp"

namespace strata::cli {
namespace {

struct ViewOptions : PipelineOptions {
  int frames = 0;          // 0: until the window closes
  std::string screenshot;  // written after the last frame
};

// The pipeline's file was edited: load it again, keeping the camera; a file that no longer loads leaves the
// pipeline as it was, and says why in the panel and on stderr.
void reload(Engine& engine, viewer::ParameterPanel& panel) {
  try {
    engine.reload();
    panel.report({});
  } catch (const Error& error) {
    std::fprintf(stderr, "%s\n", error.what());
    panel.report(error.what());
  }
}

void view(const ViewOptions& options) {
  GlfwWindow window(options.size.width, options.size.height, "Strata - " + options.pipeline, options.glDebug);
  enableGlDebugOutput(options.glDebug);
  Engine engine;
  engine.load(options.pipeline, options.overrides);
  viewer::PanelOverlay overlay(window);  // after the window's own input callbacks, which ImGui chains
  viewer::ParameterPanel panel;
  viewer::PipelineWatcher watcher(options.pipeline);
  int width = 0, height = 0;
  // Made per event: a change in the panel may load the pipeline again, and with it the body.
  const auto controls = [&] { return OrbitControls(engine.pipeline().body, engine.camera()); };
  window.setPointerInput({[&](double dx, double dy, int button) {
                            if (!overlay.wantsPointer()) controls().drag(dx, dy, button, height);
                          },
                          [&](double steps) {
                            if (!overlay.wantsPointer()) controls().scroll(steps);
                          }});
  const FrameOutput* frame = nullptr;
  for (int count = 0; !window.shouldClose() && (options.frames == 0 || count < options.frames); ++count) {
    window.pollEvents();
    if (watcher.changed()) reload(engine, panel);
    window.framebufferSize(width, height);
    if (width < 1 || height < 1) continue;  // minimised
    frame = &engine.render(width, height);
    glBlitNamedFramebuffer(frame->frame().id(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
    overlay.begin();
    panel.draw(engine);
    viewer::drawScenePanel(engine);
    overlay.end();
    window.swapBuffers();
  }
  if (frame && !options.screenshot.empty()) frame->write(options.screenshot);
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand("view", "show a pipeline in a window: drag to orbit, right-drag to turn "
                                                 "and tilt, scroll to zoom");
  addPipelineOptions(*command, *options);
  command->add_option("--frames", options->frames, "close after this many frames (default: when the window closes)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--screenshot", options->screenshot, "write the last frame to this PNG file");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { view(*options); }); });
}

}  // namespace strata::cli
