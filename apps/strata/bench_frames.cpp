#include "bench_frames.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <strata/gl.hpp>

#include "path_frames.hpp"

namespace strata::cli {
namespace {

// The wall time of one frame as a viewer sees it: render() submits the frame's GL work and glFinish waits
// for the GPU to do it, so the time includes both (a viewer's buffer swap waits the same way).
double timedFrameMs(Engine& engine, int width, int height) {
  const auto start = std::chrono::steady_clock::now();
  engine.render(width, height);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

BenchFrame measuredFrame(Engine& engine, double frameMs, std::uint64_t uploadedBefore) {
  const FrameStatistics& frame = engine.statistics();
  const GeometryStatistics geometry = engine.geometryStatistics();
  const PageCacheStatistics& pages = engine.pageCacheStatistics();
  return {.frameMs = frameMs,
          .prepareMs = frame.prepareMs,
          .renderMs = frame.renderMs,
          .visibilityMs = geometry.visibilityMs,
          .subdivisionMs = geometry.subdivisionMs,
          .rasterisationMs = geometry.rasterisationMs,
          .patches = geometry.patches,
          .vertices = geometry.vertices,
          .triangles = geometry.triangles,
          .pagesResident = pages.resident,
          .pagesWanted = pages.wanted,
          .pageFaults = pages.missing,
          .pagesUploaded = pages.uploaded,
          .uploadedThisFrame = pages.uploaded - uploadedBefore,
          .gpuBytes = pages.gpuBytes,
          .processBytes = processResidentBytes(),
          .openFiles = openFileCount(),
          .passes = engine.passTimes()};
}

}  // namespace

std::vector<BenchFrame> benchAlongPath(Engine& engine, const CameraPath& path, int frames, int laps, int width,
                                       int height, const std::function<void(int)>& progress) {
  const PathFrames spacing = pathFrames(path, std::max(2, (frames + laps - 1) / laps));
  std::vector<BenchFrame> measured;
  measured.reserve(std::size_t(frames));
  for (int frame = 0; frame < frames; ++frame) {
    const double fraction = spacing.fractionOf(frame % spacing.count);
    engine.camera() = path.atFraction(fraction);
    const std::uint64_t uploadedBefore = engine.pageCacheStatistics().uploaded;
    const double frameMs = timedFrameMs(engine, width, height);
    BenchFrame row = measuredFrame(engine, frameMs, uploadedBefore);
    row.frame = frame;
    row.seconds = fraction * spacing.duration;
    row.altitude = engine.camera().altitude;
    measured.push_back(row);
    if (progress) progress(frame);
  }
  return measured;
}

std::uint64_t processResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      std::uint64_t kilobytes = 0;
      status >> kilobytes;
      return kilobytes * 1024;
    }
    status.ignore(4096, '\n');
  }
  return 0;
}

int openFileCount() {
  std::error_code error;
  const std::filesystem::directory_iterator descriptors("/proc/self/fd", error);
  if (error) return 0;
  return int(std::distance(begin(descriptors), end(descriptors))) - 1;  // less the iterator's own
}

}  // namespace strata::cli
