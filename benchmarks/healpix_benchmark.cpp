// strata-bench-healpix: geometry.healpix's frame time against its detail threshold (vertices wanted per
// pixel), at the paper's 1024x768, so that it can be read beside the paper's table (digest 004 section 5:
// thresholds 0.005, 0.01, 0.2 and 1.0 gave 105, 75, 24 and 9 fps, shaded DEM). The planet is
// source.procedural's on a Mars-sized body, unexaggerated, seen whole from orbit and near the ground at a
// steep angle (procedural_mars_pipeline.hpp). STRATA_BENCH_HEALPIX=reduced times fewer frames, for llvmpipe;
// unset, the full set (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <strata/engine.hpp>
#include <strata/gl.hpp>

#include "headless_main.hpp"
#include "procedural_mars_pipeline.hpp"

namespace {

namespace fs = std::filesystem;

// The paper's window and thresholds.
constexpr int kWidth = 1024, kHeight = 768;
const std::vector<std::string> kThresholds = {"0.005", "0.01", "0.2", "1.0"};

// The first frames compile programs on use and JIT them on llvmpipe; the selection itself is stateless,
// so a frame is typical from the second on.
constexpr int kWarmUpFrames = 2;

struct Scene {
  std::string name;
  strata::Camera camera;
};

// One configuration: the pipeline loaded once with the threshold (as `--set` would), warmed up, then one
// frame per iteration, waited for with glFinish so that the wall time holds the GPU's work (on llvmpipe the
// timer query does not). Counters are means per frame.
void benchmarkHealpix(benchmark::State& state, const fs::path& pipeline, const Scene& scene,
                      const std::string& threshold) {
  strata::Engine engine;
  engine.load(pipeline, {"nodes.terrain.threshold=" + threshold});
  engine.camera() = scene.camera;
  for (int i = 0; i < kWarmUpFrames; ++i) engine.render(kWidth, kHeight);
  glFinish();
  double frameMs = 0, visibilityMs = 0, rasterMs = 0, nodes = 0, vertices = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    engine.render(kWidth, kHeight);
    glFinish();
    frameMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const strata::GeometryStatistics geometry = engine.geometryStatistics();
    visibilityMs += geometry.visibilityMs, rasterMs += geometry.rasterisationMs;
    nodes += geometry.patches, vertices += double(geometry.vertices);
  }
  using benchmark::Counter;
  state.counters["frame_ms"] = Counter(frameMs, Counter::kAvgIterations);
  state.counters["visibility_ms"] = Counter(visibilityMs, Counter::kAvgIterations);
  state.counters["raster_ms"] = Counter(rasterMs, Counter::kAvgIterations);
  state.counters["nodes"] = Counter(nodes, Counter::kAvgIterations);
  state.counters["vertices"] = Counter(vertices, Counter::kAvgIterations);
  // What the threshold asks for, to set beside it: every vertex of every node drawn, off screen or not.
  state.counters["vertices_per_pixel"] = Counter(vertices / (double(kWidth) * kHeight), Counter::kAvgIterations);
  // The paper's unit; from the wall time, as frame_ms.
  state.counters["fps"] = Counter(double(state.iterations()) * 1000.0 / frameMs);
}

// Every threshold from both views. The full set times 300 frames each (minutes on a GPU); the reduced one,
// for llvmpipe where a fine frame takes seconds, times 3 and leaves out the near view at threshold 1.0 (30
// million vertices, some 36 s a frame on 2 cores), the whole run within about 3 minutes.
void registerBenchmarks(const fs::path& pipeline) {
  const char* choice = std::getenv("STRATA_BENCH_HEALPIX");
  const bool reduced = choice && std::string_view(choice) == "reduced";
  const std::vector<Scene> scenes = {{"whole", strata::bench::wholeMarsView()},
                                     {"near", strata::bench::nearMarsView()}};
  for (const Scene& scene : scenes)
    for (const std::string& threshold : kThresholds) {
      if (reduced && scene.name == "near" && threshold == "1.0") continue;
      const std::string name = "healpix/view:" + scene.name + "/threshold:" + threshold;
      benchmark::RegisterBenchmark(name.c_str(), benchmarkHealpix, pipeline, scene, threshold)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(reduced ? 3 : 300);
    }
}

}  // namespace

int main(int argc, char** argv) {
  return strata::bench::runHeadless(argc, argv, [] {
    registerBenchmarks(strata::bench::writeProceduralMarsPipeline("strata-bench-healpix", "geometry.healpix"));
  });
}
