#include "command_options.hpp"

#include <cstdio>

#include <strata/error.hpp>

namespace strata::cli {

std::string parseSize(const std::string& text, FrameSize& size) {
  int width = 0, height = 0;
  char separator = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &separator, &height, &rest) != 3 || separator != 'x')
    return "size must be WIDTHxHEIGHT, e.g. 1920x1080";
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    return "size must be between 1x1 and 16384x16384 pixels";
  size = {width, height};
  return {};
}

void addPipelineOptions(CLI::App& command, PipelineOptions& options) {
  command.add_option("pipeline", options.pipeline, "the pipeline file (YAML)")->required();  // the loader reports a missing file
  command.add_option("--set", options.overrides,
                     "override a value of the pipeline: PATH=VALUE, e.g. camera.altitude=5000 or nodes.relief.scale=50")
      ->allow_extra_args(false)
      ->take_all();
  command.add_option_function<std::string>(
             "--size", [&options](const std::string& text) {
               if (auto problem = parseSize(text, options.size); !problem.empty()) throw CLI::ValidationError("--size", problem);
             },
             "frame size WIDTHxHEIGHT (default 1280x720)")
      ->type_name("WxH");
  command.add_flag("--gl-debug", options.glDebug, "log every OpenGL debug message, not only errors");
}

int reportingErrors(const std::function<void()>& command) {
  try {
    command();
    return 0;
  } catch (const Error& error) {
    std::fprintf(stderr, "%s\n", error.what());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "strata: error: %s\n", error.what());
  }
  return 1;
}

}  // namespace strata::cli
