#include <cstdio>
#include <memory>

#include <strata/engine.hpp>
#include <strata/viewer/viewer.hpp>
#include <strata/window/glfw_window.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

struct ViewOptions : PipelineOptions {
  int frames = 0;          // 0: until the window closes
  std::string screenshot;  // written after the last frame
};

void view(const ViewOptions& options) {
  GlfwWindow window(options.size.width, options.size.height, "Strata - " + options.pipeline, options.glDebug);
  enableGlDebugOutput(options.glDebug);
  Engine engine;
  engine.load(options.pipeline, options.overrides);
  viewer::Viewer viewer(window, engine);
  const FrameOutput* frame = nullptr;
  for (int count = 0; !window.shouldClose() && (options.frames == 0 || count < options.frames); ++count)
    if (const FrameOutput* drawn = viewer.frame()) frame = drawn;
  if (frame && !options.screenshot.empty()) frame->write(options.screenshot);
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand("view", "show a pipeline in a window: drag or the arrows to orbit, "
                                                 "right-drag to turn and tilt, scroll or + and - to zoom, Home to "
                                                 "start again; panels of parameters and of the scene");
  addPipelineOptions(*command, *options);
  command->add_option("--frames", options->frames, "close after this many frames (default: when the window closes)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--screenshot", options->screenshot, "write the last frame to this PNG file");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { view(*options); }); });
}

}  // namespace strata::cli
