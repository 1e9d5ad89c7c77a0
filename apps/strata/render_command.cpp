#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <strata/error.hpp>
#include <strata/gl/context.hpp>
#include <strata/host/camera_path.hpp>
#include <strata/host/engine.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/plugin/output.hpp>

#include "command_options.hpp"
#include "commands.hpp"
#include "date_sweep.hpp"
#include "output_files.hpp"
#include "path_frames.hpp"
#include "video_encoding.hpp"

namespace strata::cli {
namespace {

struct RenderOptions : PipelineOptions {
  std::string output;  // default: out/<pipeline name>.png, or out/<pipeline name>_%04d.png for a sequence
  bool stats = false;
  std::string dates;       // --dates FIRST/LAST: a sweep through the scene's date
  std::string path;        // --path FILE: a flight along a camera path
  int frames = 0;          // of a sweep or a flight; 0: not given
  bool overwrite = false;  // --overwrite: existing outputs may be replaced (never the pipeline's own files)
};

// What the last frame made and cost, for --stats.
void printStatistics(const Engine& engine) {
  const FrameStatistics& frame = engine.statistics();
  const GeometryStatistics geometry = engine.geometryStatistics();
  const PageCacheStatistics& pages = engine.pageCacheStatistics();
  std::printf(
      "strata: last of %llu frames: %d patches, %llu vertices, %llu triangles\n"
      "  geometry: visibility %.2f ms (CPU), subdivision %.2f ms, rasterisation %.2f ms (GPU)\n"
      "  frame: prepare %.2f ms, render %.2f ms (CPU, to submit)\n"
      "  page cache: %d of %d slots in use (%d pinned), %llu uploaded, %llu evicted, %llu unreadable\n",
      static_cast<unsigned long long>(frame.frame), geometry.patches,
      static_cast<unsigned long long>(geometry.vertices), static_cast<unsigned long long>(geometry.triangles),
      geometry.visibilityMs, geometry.subdivisionMs, geometry.rasterisationMs, frame.prepareMs, frame.renderMs,
      pages.resident, pages.capacity, pages.pinned, static_cast<unsigned long long>(pages.uploaded),
      static_cast<unsigned long long>(pages.evicted), static_cast<unsigned long long>(pages.failed));
}

std::string outputOf(const RenderOptions& options, const char* suffix) {
  if (!options.output.empty()) return options.output;
  return (std::filesystem::path("out") / (std::filesystem::path(options.pipeline).stem().string() + suffix)).string();
}

// The file name pattern of a sequence's frames: -o's, or out/<pipeline>_%04d.png.
std::string sequencePattern(const RenderOptions& options) {
  const std::string pattern = outputOf(options, "_%04d.png");
  checkFramePattern(pattern);
  return pattern;
}

void writeFrame(const FrameOutput& frame, const std::filesystem::path& target, OutputFiles& files) {
  files.write(target, [&](const std::filesystem::path& partial) { frame.write(partial); });
}

// Each frame of a sweep waits for every page it wants (renderComplete), so the sequence is the same on every
// run, whatever the loaders' timing.
void renderDateSweep(Engine& engine, const DateSweep& sweep, const std::string& pattern, FrameSize size,
                     OutputFiles& files) {
  for (int frame = 0; frame < sweep.frames; ++frame) {
    engine.date() = sweep.dateOf(frame);
    writeFrame(engine.renderComplete(size.width, size.height), frameFileName(pattern, frame), files);
  }
  std::printf("strata: wrote %d frames %s from %s to %s", sweep.frames, pattern.c_str(),
              formatIsoDate(sweep.first).c_str(), formatIsoDate(sweep.last).c_str());
}

// A video's frames go to the scratch folder, where ffmpeg encodes them; the video is then moved into place.
// Should ffmpeg fail, the frames are kept there for the user.
void encodeFlight(const RenderOptions& options, const std::filesystem::path& ffmpeg, const std::string& pattern,
                  double framesPerSecond, OutputFiles& files) {
  ScratchDirectory& scratch = files.scratchFor(options.output);
  const std::filesystem::path video = scratch.path() / std::filesystem::path(options.output).filename();
  try {
    encodeVideo(ffmpeg, pattern, framesPerSecond, video);
  } catch (const Error&) {
    scratch.keep();
    throw;
  }
  files.publish(video, options.output);
  std::printf(", encoded %s at %.2f frames/s", options.output.c_str(), framesPerSecond);
}

// A flight along a camera path: each frame waits for every page it wants, like a sweep's, and for the
// geometry to catch up with the camera, so that the same path renders to the same frames on every run; then,
// for a video, ffmpeg encodes them.
void renderFlight(Engine& engine, const RenderOptions& options, const std::filesystem::path& ffmpeg,
                  OutputFiles& files) {
  // A flight is measured over the pipeline's body, known once it loads.
  const CameraPath path = readCameraPath(options.path, engine.cameraBody());
  const PathFrames frames = pathFrames(path, options.frames);
  const std::string pattern =
      ffmpeg.empty() ? sequencePattern(options) : videoFramePattern(files.scratchFor(options.output).path());
  for (int frame = 0; frame < frames.count; ++frame) {
    engine.camera() = path.atFraction(frames.fractionOf(frame));
    const FrameOutput& output = engine.renderSettled(options.size.width, options.size.height);
    if (ffmpeg.empty())
      writeFrame(output, frameFileName(pattern, frame), files);
    else
      output.write(frameFileName(pattern, frame));
  }
  std::printf("strata: wrote %d frames %s along %s (%.1f s)", frames.count,
              ffmpeg.empty() ? pattern.c_str() : "for the video", options.path.c_str(), frames.duration);
  if (!ffmpeg.empty()) encodeFlight(options, ffmpeg, pattern, frames.framesPerSecond(), files);
}

void requireSequenceForFrames(const RenderOptions& options) {
  if (options.frames != 0 && options.dates.empty() && options.path.empty())
    throw Error(SourceLocation{"--frames"}, "--frames counts the frames of a sequence, and none was asked for",
                "give --dates FIRST/LAST or --path FILE with it");
}

// Every file the command will write: the image, each frame of a sequence, or the video.
std::vector<std::filesystem::path> targetsOf(const RenderOptions& options, int sequenceFrames, bool video) {
  if (video) return {options.output};
  if (sequenceFrames == 0) return {outputOf(options, ".png")};
  const std::string pattern = sequencePattern(options);
  std::vector<std::filesystem::path> targets;
  for (int frame = 0; frame < sequenceFrames; ++frame) targets.emplace_back(frameFileName(pattern, frame));
  return targets;
}

// What the command reads before its pipeline loads: the pipeline and the camera path.
OutputRules readFiles(const RenderOptions& options) {
  OutputRules rules{options.overwrite, {options.pipeline}};
  if (!options.path.empty()) rules.inputs.emplace_back(options.path);
  return rules;
}

void render(const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  requireSequenceForFrames(options);
  const bool sweeping = !options.dates.empty(), flying = !options.path.empty();
  const DateSweep sweep = sweeping ? parseDateSweep(options.dates, options.frames) : DateSweep{};
  // The outputs, the encoder and the path file are checked before the pipeline loads: a mistake costs no
  // time. The path is read again over the pipeline's body once it has loaded.
  const bool video = flying && isVideoFile(options.output);
  const std::filesystem::path ffmpeg = video ? requireFfmpeg() : std::filesystem::path{};
  const int flightFrames = flying ? pathFrames(readCameraPath(options.path, Body{}), options.frames).count : 0;
  const std::vector<std::filesystem::path> targets = targetsOf(options, sweeping ? sweep.frames : flightFrames, video);
  if (!video) imageFormatOf(targets.front());  // every frame of a sequence has the pattern's extension
  OutputFiles files(targets, readFiles(options), SourceLocation{"-o"});
  auto context = createHeadlessContext(options.glDebug);
  enableGlDebugOutput(options.glDebug);
  Engine engine;
  engine.load(options.pipeline, options.overrides);
  files.refuse(pipelineInputFiles(engine.pipeline()));
  if (sweeping) {
    renderDateSweep(engine, sweep, sequencePattern(options), options.size, files);
  } else if (flying) {
    renderFlight(engine, options, ffmpeg, files);
  } else {
    const std::filesystem::path file = outputOf(options, ".png");
    writeFrame(engine.renderComplete(options.size.width, options.size.height), file, files);
    std::printf("strata: wrote %s", file.c_str());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(" (%dx%d) in %.1f s on %s\n", options.size.width, options.size.height, seconds,
              currentGlInfo().renderer.c_str());
  if (options.stats) printStatistics(engine);
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "render a pipeline headless to an image file");
  addPipelineOptions(*command, *options);
  command->add_option("-o,--output", options->output,
                      "the image to write, PNG or TIFF by its extension (default out/<pipeline>.png); for a "
                      "sequence, a pattern such as out/f_%04d.png, or for --path a video (.mp4, .webm)");
  command->add_flag("--overwrite", options->overwrite,
                    "replace outputs that exist (never a file the pipeline reads, nor one reached through a link)");
  command
      ->add_option("--dates", options->dates,
                   "render a sequence through the scene's date: FIRST/LAST, e.g. 2004-01-01/2004-12-31, with --frames "
                   "and -o naming each frame's file with a field such as %04d")
      ->type_name("FIRST/LAST");
  command
      ->add_option("--path", options->path,
                   "render a flight along a camera path file (docs/camera-paths.md), with -o naming each frame's "
                   "file with a field such as %05d, or a video (.mp4, .webm) when ffmpeg is installed")
      ->type_name("FILE")
      ->excludes("--dates");
  command->add_option("--frames", options->frames,
                      "frames of the --dates or --path sequence, evenly spaced, both ends included (--path: 30 a "
                      "second of the path when not given)");
  command->add_flag("--stats", options->stats,
                    "print the last frame's patches, vertices, triangles and phase times, and the page cache's state");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { render(*options); }); });
}

}  // namespace strata::cli
