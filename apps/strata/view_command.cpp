#include <cstdio>
#include <memory>

#include <strata/host/engine.hpp>
#include <strata/viewer/viewer.hpp>
#include <strata/window/glfw_window.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

struct ViewOptions : PipelineOptions {
  int frames = 0;                  // 0: until the window closes
  std::string screenshot;          // written after the last frame
  FrameSize screenshotSize{0, 0};  // 0 x 0: the window's
};

void view(const ViewOptions& options) {
  GlfwWindow window(options.size.width, options.size.height, "Strata - " + options.pipeline, options.glDebug);
  enableGlDebugOutput(options.glDebug);
  Engine engine;
  engine.load(options.pipeline, options.overrides);
  viewer::Viewer viewer(window, engine);
  for (int count = 0; !window.shouldClose() && (options.frames == 0 || count < options.frames); ++count) viewer.frame();
  if (options.screenshot.empty()) return;
  FrameSize size = options.screenshotSize;
  if (size.width == 0) window.framebufferSize(size.width, size.height);
  viewer.screenshot(options.screenshot, size.width, size.height);
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand("view",
                                         "show a pipeline in a window: drag or the arrows to orbit, "
                                         "right-drag to turn and tilt, scroll or + and - to zoom, W and S to "
                                         "fly, Home to start again; panels of parameters and of the scene");
  addPipelineOptions(*command, *options);
  command->add_option("--frames", options->frames, "close after this many frames (default: when the window closes)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--screenshot", options->screenshot, "write the view when the window closes to this PNG file");
  command
      ->add_option_function<std::string>(
          "--screenshot-size",
          [options](const std::string& text) {
            if (auto problem = parseSize(text, options->screenshotSize); !problem.empty())
              throw CLI::ValidationError("--screenshot-size", problem);
          },
          "the screenshot's size WIDTHxHEIGHT, any (default: the window's)")
      ->type_name("WxH");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { view(*options); }); });
}

}  // namespace strata::cli
