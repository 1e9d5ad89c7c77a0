// strata-bench-clipmap: geometry.clipmap's frame time against the levels a view draws, at the paper's 1280x960,
// laid out as [Clasen & Hege 2006, §5.2]'s three views (a GeForce 6800: standing on the ground, levels 6 to 21,
// about 330,000 triangles, 25 fps; an aircraft's view, levels 3 to 9, about 140,000, 40 fps; from space, levels 1
// to 4, about 100,000, 65 fps). The planet is the procedural Mars every generator's benchmark flies over
// (procedural_mars_pipeline.hpp), heights within +-12 km; the views are its whole planet from 8,000 km and its near
// view 20 km up tilted 70 degrees, beside the paper's: an aircraft 15 km up tilted 75 degrees, and 2 m above the
// ground looking at the horizon. The other generators are timed on the same whole and near views by their own
// benchmarks.
// STRATA_BENCH_CLIPMAP=reduced times 3 frames a view, for llvmpipe; unset, 300 (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <strata/gl.hpp>
#include <strata/host/engine.hpp>

#include "headless_main.hpp"
#include "procedural_mars_pipeline.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1280, kHeight = 960;  // the paper's screen
// The first frames compile programs on use and JIT them on llvmpipe; nothing else carries over between frames.
constexpr int kWarmUpFrames = 2;

struct Scene {
  std::string name;
  strata::Camera camera;
};

// One view: the pipeline loaded once, warmed up, then one frame per iteration, waited for with glFinish so that the
// wall time holds the GPU's work. Counters are means per frame.
void benchmarkClipmap(benchmark::State& state, const fs::path& pipeline, const Scene& scene) {
  strata::Engine engine;
  engine.load(pipeline);
  engine.camera() = scene.camera;
  strata::bench::warmUp(engine, kWidth, kHeight, kWarmUpFrames);
  double frameMs = 0, terrainMs = 0, heightsMs = 0, visibilityMs = 0, levels = 0, triangles = 0;
  for (auto _ : state) {
    frameMs += strata::bench::timedFrameMs(engine, kWidth, kHeight);
    const strata::GeometryStatistics geometry = engine.geometryStatistics();
    visibilityMs += geometry.visibilityMs, levels += geometry.patches, triangles += double(geometry.triangles);
    heightsMs += geometry.subdivisionMs;
    for (const strata::PassTime& pass : engine.passTimes()) terrainMs += pass.node == "terrain" ? pass.gpuMs : 0.0;
  }
  // terrain_ms: the geometry's own pass (GL_TIMESTAMP queries around it), on llvmpipe about the time to submit it,
  // which holds the vertex shading of every drawn vertex; the rest of the frame is the procedural colours'
  // composition. heights_ms: of it, the height clipmaps' sampling (a GPU timer), none once a still view's windows
  // are in place.
  strata::bench::setMeans(state, {{"frame_ms", frameMs},
                                  {"terrain_ms", terrainMs},
                                  {"heights_ms", heightsMs},
                                  {"visibility_ms", visibilityMs},
                                  {"levels", levels},
                                  {"triangles", triangles}});
  state.counters["fps"] = double(state.iterations()) * 1000.0 / frameMs;  // the paper's unit
}

void registerBenchmarks(const fs::path& pipeline) {
  const bool reduced = strata::bench::reducedRun("STRATA_BENCH_CLIPMAP");
  const std::vector<Scene> scenes = {
      {"whole", strata::bench::wholeMarsView()},
      {"near", strata::bench::nearMarsView()},
      {"aircraft", {.lon = 30, .lat = 25, .altitude = 15000, .heading = 0, .tilt = 75, .fov = 45}},
      {"ground", {.lon = 30, .lat = 25, .altitude = 2, .heading = 0, .tilt = 88, .fov = 45}}};
  for (const Scene& scene : scenes)
    strata::bench::registerFrames("clipmap/view:" + scene.name, reduced ? 3 : 300, benchmarkClipmap, pipeline, scene);
}

}  // namespace

int main(int argc, char** argv) {
  return strata::bench::runHeadless(argc, argv, [] {
    registerBenchmarks(strata::bench::writeProceduralMarsPipeline("strata-bench-clipmap", "geometry.clipmap"));
  });
}
