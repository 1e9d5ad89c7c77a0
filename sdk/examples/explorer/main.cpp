// mars-explorer: a domain viewer built on an installed Strata SDK. The host owns the window, the event
// loop and the UI (GLFW and Dear ImGui here); Strata renders each frame into a framebuffer on the host's
// OpenGL context, and the host puts it on screen and draws its own controls over it. docs/sdk/embedding.md
// explains the contract.
#include <cstdio>
#include <exception>
#include <stdexcept>

#include <strata/error.hpp>
#include <strata/gl.hpp>
#include <strata/host/engine.hpp>
#include <strata/plugin/output.hpp>

#include "explorer_options.hpp"
#include "explorer_panel.hpp"
#include "explorer_window.hpp"
#include "sample_scene.hpp"

namespace explorer {
namespace {

// The settings the command line asks for, made as the panel's controls make them.
void applyOptions(const ExplorerOptions& options, ExplorerPanel& panel) {
  for (const std::string& layer : options.hidden) panel.showLayer(layer, false);
  if (options.date) panel.setDate(*options.date);
  if (options.altitude) panel.setAltitude(*options.altitude);
}

// One frame: the engine's image copied into the window, the panel over it. A screenshot waits for every
// page the view wants (renderComplete), so that it shows the finished frame.
void drawFrame(strata::Engine& engine, ExplorerWindow& window, ExplorerPanel& panel, int width, int height,
               bool complete) {
  const strata::FrameOutput& frame = complete ? engine.renderComplete(width, height) : engine.render(width, height);
  glBlitNamedFramebuffer(frame.frame().id(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
  window.beginPanel();
  panel.draw();
  window.endPanel();
}

int run(const ExplorerOptions& options) {
  ExplorerWindow window(options.width, options.height, "Mars explorer");
  strata::Engine engine;  // on the window's context, current on this thread: every call stays on it
  if (options.pipeline.empty())
    engine.load(sampleScene());
  else
    engine.load(options.pipeline);
  ExplorerPanel panel(engine);
  applyOptions(options, panel);
  for (int frames = 1; window.open(); ++frames) {
    int width = 0, height = 0;
    window.beginFrame(width, height);
    if (width < 1 || height < 1) continue;  // minimised
    drawFrame(engine, window, panel, width, height, options.screenshot.has_value());
    if (options.screenshot && frames >= options.frames) {
      strata::writeImage(*options.screenshot, width, height, window.readBack(width, height));
      std::printf("mars-explorer: wrote %s (%dx%d)\n", options.screenshot->c_str(), width, height);
      return 0;
    }
    window.endFrame();
  }
  return 0;
}

}  // namespace
}  // namespace explorer

int main(int argc, char** argv) {
  try {
    return explorer::run(explorer::parseOptions(argc, argv));
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "mars-explorer: %s\n%s", error.what(), explorer::usage().c_str());
    return 2;
  } catch (const std::exception& error) {  // strata::Error says where and how to fix it
    std::fprintf(stderr, "mars-explorer: %s\n", error.what());
    return 1;
  }
}
