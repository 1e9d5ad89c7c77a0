#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <strata/host/camera_path.hpp>
#include <strata/host/engine.hpp>

namespace strata::cli {

// What one benchmark frame cost and made (`strata bench`, docs/benchmarks.md): a row of its CSV.
struct BenchFrame {
  int frame = 0;
  double seconds = 0.0;          // along the path
  double altitude = 0.0;         // m
  double frameMs = 0.0;          // wall time of Engine::render and a glFinish: CPU and GPU work of the frame
  double prepareMs = 0.0;        // CPU phase (Engine::statistics)
  double renderMs = 0.0;         // GL phase, CPU time to submit
  double visibilityMs = 0.0;     // CPU: the patch tree (Engine::geometryStatistics)
  double subdivisionMs = 0.0;    // GPU timer query
  double rasterisationMs = 0.0;  // GPU timer query
  int patches = 0;
  std::uint64_t vertices = 0;
  std::uint64_t triangles = 0;
  int pagesResident = 0;
  int pagesWanted = 0;
  // Page faults: pages the frame wanted that were not resident, queued for or being read by the loaders
  // when it ended (PageCacheStatistics::loading); a faulting page stays one until it is uploaded.
  int pageFaults = 0;
  std::uint64_t pagesUploaded = 0;  // since the pipeline loaded
  std::uint64_t uploadedThisFrame = 0;
  std::uint64_t gpuBytes = 0;      // the page cache's atlases, index and upload buffers
  std::uint64_t processBytes = 0;  // resident set of the process (VmRSS)
  int openFiles = 0;               // the process's open file descriptors (/proc/self/fd)
  std::vector<PassTime> passes;    // each node's GPU time (Engine::passTimes)
};

// Renders `frames` frames evenly spaced in time along `path`, flown `laps` times one after another, as a
// viewer draws them (Engine::render: pages load asynchronously and coarser ones stand in), timing each,
// from the cache the engine has (empty just after load). `progress`, when given, is told the number of
// each frame done. Many laps make a soak run: the cache fills, and memory must then stay flat.
std::vector<BenchFrame> benchAlongPath(Engine& engine, const CameraPath& path, int frames, int laps, int width,
                                       int height, const std::function<void(int)>& progress = {});

// The process's resident set in bytes, from /proc/self/status (VmRSS); 0 where there is none.
std::uint64_t processResidentBytes();
// The process's open file descriptors; 0 where /proc/self/fd cannot be read.
int openFileCount();

}  // namespace strata::cli
