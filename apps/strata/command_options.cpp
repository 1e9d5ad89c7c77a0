#include "command_options.hpp"

#include <charconv>
#include <system_error>

#include <strata/error.hpp>

namespace strata::cli {

// WIDTHxHEIGHT read digit by digit: sscanf's %d wraps numbers beyond an int (4294967297 read as 1).
std::string parseSize(const std::string& text, FrameSize& size) {
  const char* end = text.data() + text.size();
  long long width = 0, height = 0;
  const auto [afterWidth, widthError] = std::from_chars(text.data(), end, width);
  // Digits beyond a long long are out of range, not malformed: from_chars still steps over them.
  const bool separated = widthError != std::errc::invalid_argument && afterWidth != end && *afterWidth == 'x';
  const auto [afterHeight, heightError] = separated ? std::from_chars(afterWidth + 1, end, height)
                                                    : std::from_chars_result{end, std::errc::invalid_argument};
  if (heightError == std::errc::invalid_argument || afterHeight != end)
    return "size must be WIDTHxHEIGHT, e.g. 1920x1080";
  constexpr long long kMost = 16384;
  if (widthError != std::errc() || heightError != std::errc() || width < 1 || height < 1 || width > kMost ||
      height > kMost)
    return "size must be between 1x1 and 16384x16384 pixels, not " + text;
  size = {int(width), int(height)};
  return {};
}

void addPipelineOptions(CLI::App& command, PipelineOptions& options) {
  command.add_option("pipeline", options.pipeline, "the pipeline file (YAML)")
      ->required();  // the loader reports a missing file
  command
      .add_option("--set", options.overrides,
                  "override a value of the pipeline: PATH=VALUE, e.g. camera.altitude=5000 or nodes.relief.scale=50")
      ->allow_extra_args(false)
      ->take_all();
  command
      .add_option_function<std::string>(
          "--size",
          [&options](const std::string& text) {
            if (auto problem = parseSize(text, options.size); !problem.empty())
              throw CLI::ValidationError("--size", problem);
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
