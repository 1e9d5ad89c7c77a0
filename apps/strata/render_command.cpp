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
  bool stats = false;
};

// What the last frame made and cost, for --stats.
void printStatistics(const Engine& engine) {
  const FrameStatistics& frame = engine.statistics();
  const GeometryStatistics geometry = engine.geometryStatistics();
  const PageCacheStatistics& pages = engine.pageCacheStatistics();
  std::printf("strata: last of %llu frames: %d patches, %llu vertices, %llu triangles\n"
              "  geometry: visibility %.2f ms (CPU), subdivision %.2f ms, rasterisation %.2f ms (GPU)\n"
              "  frame: prepare %.2f ms, render %.2f ms (CPU, to submit)\n"
              "  page cache: %d of %d slots in use (%d pinned), %llu uploaded, %llu evicted, %llu unreadable\n",
              static_cast<unsigned long long>(frame.frame), geometry.patches,
              static_cast<unsigned long long>(geometry.vertices), static_cast<unsigned long long>(geometry.triangles),
              geometry.visibilityMs, geometry.subdivisionMs, geometry.rasterisationMs, frame.prepareMs, frame.renderMs,
              pages.resident, pages.capacity, pages.pinned, static_cast<unsigned long long>(pages.uploaded),
              static_cast<unsigned long long>(pages.evicted), static_cast<unsigned long long>(pages.failed));
}

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
  if (options.stats) printStatistics(engine);
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "render a pipeline headless to an image file");
  addPipelineOptions(*command, *options);
  command->add_option("-o,--output", options->output, "the PNG file to write (default out/<pipeline>.png)");
  command->add_flag("--stats", options->stats,
                    "print the last frame's patches, vertices, triangles and phase times, and the page cache's state");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { render(*options); }); });
}

}  // namespace strata::cli
