#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <strata/engine.hpp>
#include <strata/gl/context.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

struct RenderOptions : PipelineOptions {
  std::string output;  // default: out/<pipeline name>.png
};

void render(const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto context = createHeadlessContext(options.glDebug);
  enableGlDebugOutput(options.glDebug);
  Engine engine;
  engine.load(options.pipeline, options.overrides);
  const FrameOutput& frame = engine.renderComplete(options.size.width, options.size.height);
  const std::filesystem::path file =
      options.output.empty() ? std::filesystem::path("out") / (std::filesystem::path(options.pipeline).stem().string() + ".png")
                             : std::filesystem::path(options.output);
  frame.write(file);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("strata: wrote %s (%dx%d) in %.1f s on %s\n", file.c_str(), options.size.width, options.size.height,
              seconds, currentGlInfo().renderer.c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "render a pipeline headless to an image file");
  addPipelineOptions(*command, *options);
  command->add_option("-o,--output", options->output, "the PNG file to write (default out/<pipeline>.png)");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { render(*options); }); });
}

}  // namespace strata::cli
