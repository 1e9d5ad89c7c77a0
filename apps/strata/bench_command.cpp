// `strata bench`: a pipeline timed frame by frame along a camera path, to a CSV and a plot (docs/benchmarks.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <strata/error.hpp>
#include <strata/gl/context.hpp>
#include <strata/host/camera_path.hpp>
#include <strata/host/engine.hpp>
#include <strata/host/pipeline.hpp>

#include "bench_csv.hpp"
#include "bench_frames.hpp"
#include "bench_plot.hpp"
#include "bench_summary.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "output_files.hpp"

namespace strata::cli {
namespace {

namespace fs = std::filesystem;

struct BenchOptions : PipelineOptions {
  std::string path;        // default: paths/<pipeline name>.yaml beside the pipeline
  int frames = 4800;       // the benchmark of [Kooima 2008, §5.1]: 4800 frames in and back out
  int average = 10;        // ... averaged over 10 frames into 480 points
  int laps = 1;            // the path flown this many times: a soak run
  std::string output;      // default: out/bench/<pipeline name>.csv
  std::string plot;        // default: the CSV's name with .svg
  std::string compare;     // a second pipeline run on the same path
  bool overwrite = false;  // --overwrite: existing outputs may be replaced (never a file a pipeline reads)
};

fs::path pathFileOf(const BenchOptions& options) {
  if (!options.path.empty()) return options.path;
  return fs::path(options.pipeline).parent_path() / "paths" / (fs::path(options.pipeline).stem().string() + ".yaml");
}

fs::path csvFileOf(const BenchOptions& options) {
  if (!options.output.empty()) return options.output;
  return fs::path("out") / "bench" / (fs::path(options.pipeline).stem().string() + ".csv");
}

// The second pipeline's files beside the first's: <name>_compare.csv and the summary <name>_compare.txt.
fs::path compareFileOf(const fs::path& csv, const char* extension) {
  return csv.parent_path() / (csv.stem().string() + "_compare" + extension);
}

void checkOptions(const BenchOptions& options, const fs::path& pathFile) {
  // Named before the path, which is found beside it, as the loader names it.
  for (const std::string& pipeline : {options.pipeline, options.compare})
    if (!pipeline.empty() && !fs::exists(pipeline))
      throw Error(SourceLocation{pipeline}, "pipeline file not found",
                  "check the path; pipelines/ holds ready-made pipelines");
  if (options.frames < 2)
    throw Error(SourceLocation{"--frames"},
                "a benchmark takes at least 2 frames, got " + std::to_string(options.frames),
                "give --frames N with N >= 2 (Kooima 2008's benchmark: 4800)");
  if (options.average < 1)
    throw Error(SourceLocation{"--average"},
                "frames are averaged over at least 1, got " + std::to_string(options.average),
                "give --average K with K >= 1 (Kooima 2008's figures: 10)");
  if (options.laps < 1 || options.frames < 2 * options.laps)
    throw Error(SourceLocation{"--laps"},
                "the path is flown at least once, in at least 2 frames a lap; got " + std::to_string(options.laps) +
                    " laps of " + std::to_string(options.frames) + " frames",
                "give --laps N with 1 <= N <= frames / 2");
  if (!fs::exists(pathFile))
    throw Error(SourceLocation{pathFile.string()}, "no camera path file here",
                options.path.empty()
                    ? "give --path FILE (without it the path is paths/<pipeline name>.yaml beside the pipeline)"
                    : "give --path an existing file (docs/camera-paths.md)");
  readCameraPath(pathFile, Body{});  // a mistake in the path costs no time; it is read again over the body
}

// One pipeline, loaded into an engine of its own (an empty page cache), timed along the path.
std::vector<BenchFrame> benchPipeline(const std::string& pipeline, const BenchOptions& options,
                                      const fs::path& pathFile, OutputFiles& files) {
  Engine engine;
  engine.load(pipeline, options.overrides);
  files.refuse(pipelineInputFiles(engine.pipeline()));
  const CameraPath path = readCameraPath(pathFile, engine.cameraBody());
  // A tenth of the run at a time on stderr: 4800 frames take the better part of an hour on a CPU renderer.
  const auto progress = [&](int frame) {
    if ((frame + 1) % std::max(options.frames / 10, 1) == 0)
      std::fprintf(stderr, "strata: %s: frame %d of %d\n", pipeline.c_str(), frame + 1, options.frames);
  };
  return benchAlongPath(engine, path, options.frames, options.laps, options.size.width, options.size.height, progress);
}

std::string summaryLine(const FrameTimeSummary& s) {
  char text[160];
  std::snprintf(text, sizeof text, "frame ms mean %.2f, median %.2f, p95 %.2f, max %.2f", s.mean, s.median, s.p95,
                s.max);
  return text;
}

// Every file bench writes, each checked before a frame is timed: the CSV, the plot, and with --compare the
// second pipeline's CSV and the comparison.
OutputFiles outputFilesOf(const BenchOptions& options, const fs::path& csv, const fs::path& plot,
                          const fs::path& pathFile) {
  std::vector<fs::path> targets{csv, plot};
  if (!options.compare.empty()) targets.insert(targets.end(), {compareFileOf(csv, ".csv"), compareFileOf(csv, ".txt")});
  OutputRules rules{options.overwrite, {options.pipeline, pathFile}};
  if (!options.compare.empty()) rules.inputs.emplace_back(options.compare);
  return OutputFiles(targets, rules, SourceLocation{"-o"});
}

void bench(const BenchOptions& options) {
  const fs::path pathFile = pathFileOf(options), csv = csvFileOf(options);
  checkOptions(options, pathFile);
  const fs::path plot = options.plot.empty() ? fs::path(csv).replace_extension(".svg") : fs::path(options.plot);
  OutputFiles files = outputFilesOf(options, csv, plot, pathFile);
  auto context = createHeadlessContext(options.glDebug);
  enableGlDebugOutput(options.glDebug);
  const std::vector<BenchFrame> first = benchPipeline(options.pipeline, options, pathFile, files);
  files.write(csv, [&](const fs::path& partial) { writeBenchCsv(partial, first); });
  std::vector<PlotRun> runs{{options.pipeline, averageFrames(first, options.average), options.frames}};
  std::printf("strata: bench %s along %s, %d frames (%dx%d) on %s\n  %s: %s\n", options.pipeline.c_str(),
              pathFile.c_str(), options.frames, options.size.width, options.size.height,
              currentGlInfo().renderer.c_str(), options.pipeline.c_str(), summaryLine(summarise(first)).c_str());
  if (!options.compare.empty()) {
    const std::vector<BenchFrame> second = benchPipeline(options.compare, options, pathFile, files);
    files.write(compareFileOf(csv, ".csv"), [&](const fs::path& partial) { writeBenchCsv(partial, second); });
    runs.push_back({options.compare, averageFrames(second, options.average), options.frames});
    const std::string report = comparisonReport(options.pipeline, summarise(first), options.compare, summarise(second));
    files.write(compareFileOf(csv, ".txt"), [&](const fs::path& partial) { std::ofstream(partial) << report; });
    std::printf("  %s: %s\n%s", options.compare.c_str(), summaryLine(summarise(second)).c_str(), report.c_str());
  }
  files.write(plot, [&](const fs::path& partial) { writeBenchPlot(partial, runs, options.average); });
  std::printf("strata: wrote %s and %s\n", csv.c_str(), plot.c_str());
}

}  // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<BenchOptions>();
  options->size = {1024, 768};  // the baseline benchmark of [Kooima 2008, §5.1.1, Fig. 5.2]
  CLI::App* command =
      app.add_subcommand("bench", "time a pipeline frame by frame along a camera path, to a CSV and a plot");
  addPipelineOptions(*command, *options);
  command->get_option("--size")->description("frame size WIDTHxHEIGHT (default 1024x768, Kooima 2008's)");
  command
      ->add_option(
          "--path", options->path,
          "the camera path file (docs/camera-paths.md; default paths/<pipeline name>.yaml beside the pipeline)")
      ->type_name("FILE");
  command->add_option("--frames", options->frames,
                      "frames along the path, evenly spaced in time (default 4800, Kooima 2008's)");
  command->add_option("--average", options->average,
                      "frames averaged into each point of the plot (default 10, Kooima 2008's)");
  command->add_option("--laps", options->laps,
                      "fly the path this many times, --frames in all (default 1); with many, a soak run whose plot "
                      "shows memory and open files");
  command->add_option("-o,--output", options->output, "the per-frame CSV (default out/bench/<pipeline name>.csv)");
  command->add_option("--plot", options->plot, "the plot, SVG (default the CSV's name with .svg)");
  command->add_flag("--overwrite", options->overwrite,
                    "replace outputs that exist (never a file a pipeline reads, nor one reached through a link)");
  command
      ->add_option("--compare", options->compare,
                   "a second pipeline run along the same path; prints and writes its frame times over the first's")
      ->type_name("PIPELINE");
  command->footer("On a CPU renderer give a smaller --size and fewer --frames, e.g. --size 256x192 --frames 480.");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { bench(*options); }); });
}

}  // namespace strata::cli
