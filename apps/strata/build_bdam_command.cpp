#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <thread>

#include <bintree_builder.hpp>
#include <face_file.hpp>
#include <raster_heights.hpp>

#include "command_options.hpp"
#include "commands.hpp"
#include "output_files.hpp"

namespace strata::cli {
namespace {

struct BuildBdamRequest {
  std::string input, output;
  int level = -1;  // -1: the least whose leaf grid is as fine as the raster
  int divisions = 16;
  double radius = 0.0;
  double scale = 1.0;
  unsigned threads = 0;
  bool overwrite = false;
};

// The least leaf level whose grid steps (a leg of a level's triangle over `divisions`) are no longer than a texel:
// a root's legs span a face, a quarter of a great circle, and each level shortens them by sqrt(2).
int leafLevelFor(double texel, double radius, int divisions) {
  const double face = std::numbers::pi / 2.0 * radius;
  return std::clamp(int(std::ceil(2.0 * std::log2(face / (divisions * texel)))), 0, 30);
}

std::vector<std::filesystem::path> faceFiles(const std::filesystem::path& output) {
  std::vector<std::filesystem::path> files;
  for (int face = 0; face < bdam::kCubeFaces; ++face)
    files.push_back(output / ("face-" + std::to_string(face) + ".bdam"));
  return files;
}

void reportLevel(const bdam::LevelReport& report) {
  std::fprintf(stderr, "strata build-bdam: level %2d: %zu diamonds, %zu triangles, %.1f MB stored, %.1f s\n",
               report.level, report.diamonds, report.triangles, double(report.storedBytes) / 1e6, report.seconds);
}

void buildBdam(const BuildBdamRequest& request) {
  const std::vector<std::filesystem::path> targets = faceFiles(request.output);
  OutputFiles files(targets, {request.overwrite, {request.input}}, SourceLocation{"output"});
  std::unique_ptr<bdam::RasterHeights> heights;
  try {
    heights = std::make_unique<bdam::RasterHeights>(request.input);
  } catch (const std::runtime_error& error) {
    throw Error(SourceLocation{request.input}, error.what(), "give a height raster GDAL reads, in metres");
  }
  const double radius = request.radius > 0.0 ? request.radius : heights->bodyRadius();
  if (!(radius > 0.0))
    throw Error(SourceLocation{request.input}, "the raster has no CRS to take the body's radius from",
                "give it with --radius (m)");
  bdam::BuildOptions options{
      radius, request.level >= 0 ? request.level : leafLevelFor(heights->texelSize(radius), radius, request.divisions),
      request.divisions, request.threads ? request.threads : std::max(1u, std::thread::hardware_concurrency()),
      files.scratchFor(targets[0]).path()};
  std::fprintf(stderr,
               "strata build-bdam: %s on a body of radius %.0f m, leaves of level %d (%d steps a side), %u %s\n",
               request.input.c_str(), radius, options.leafLevel, options.divisions, options.threads,
               options.threads == 1 ? "thread" : "threads");
  const auto start = std::chrono::steady_clock::now();
  const bdam::BuiltBintrees bintrees = bdam::buildBintrees(
      [&heights, scale = request.scale]() -> bdam::HeightAt {
        return [sample = heights->sampler(), scale](const glm::dvec3& direction) { return scale * sample(direction); };
      },
      options, reportLevel);
  std::uintmax_t bytes = 0;
  for (int face = 0; face < bdam::kCubeFaces; ++face) {
    files.write(targets[std::size_t(face)],
                [&](const std::filesystem::path& partial) { bdam::writeFaceFile(partial, face, bintrees); });
    bytes += std::filesystem::file_size(targets[std::size_t(face)]);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("strata: wrote %s (6 face files, %.1f MB, leaves of level %d) in %.1f s on %u %s\n",
              request.output.c_str(), double(bytes) / 1e6, options.leafLevel, seconds, options.threads,
              options.threads == 1 ? "thread" : "threads");
}

}  // namespace

void addBuildBdamCommand(CLI::App& app, int& exitCode) {
  auto request = std::make_shared<BuildBdamRequest>();
  CLI::App* command = app.add_subcommand(
      "build-bdam",
      "build geometry.bdam's simplified patches of a height raster: one file per cube face (docs/bdam.md)");
  command->add_option("input", request->input, "the height raster (m; any projection GDAL and PROJ read)")->required();
  command->add_option("output", request->output, "the folder to write face-0.bdam ... face-5.bdam in")->required();
  command
      ->add_option("--level", request->level,
                   "the leaves' level, 0 to 30; default: the least whose leaf grid is as fine as the raster's texels")
      ->check(CLI::Range(0, 30));
  command
      ->add_option("--divisions", request->divisions,
                   "leaf grid steps a side; default 16: 256 triangles a patch, a few hundred as the paper's")
      ->check(CLI::Range(1, 64));
  command->add_option("--radius", request->radius, "the body's radius, m; default: the raster CRS's semi-major axis")
      ->check(CLI::PositiveNumber);
  command->add_option("--scale", request->scale,
                      "multiplies the raster's values (vertical exaggeration, or its units to metres); default 1");
  command->add_option("--threads", request->threads, "threads to build with; default: every core");
  command->add_flag("--overwrite", request->overwrite, "replace face files that exist");
  command->callback([request, &exitCode] { exitCode = reportingErrors([&] { buildBdam(*request); }); });
}

}  // namespace strata::cli
