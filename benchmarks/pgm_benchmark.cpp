// strata-bench-pgm: geometry.pgm's time against its grid of rays and the screen, laid out as Mahsman's Tables
// 6.2 (the PGM step), 6.3 (the entire frame) and 6.5 (grid = screen at standard resolutions) so that the two
// can be compared ([Mahsman 2010, §6.1, §6.2]; docs/benchmarks.md). The planet is source.procedural's on a
// Mars-sized body, unexaggerated, seen as the thesis's test cases 1 (the whole planet) and 2 (near it at a
// steep angle). Sizes are width x height, as the thesis writes 640x480; the grid's are columns x rows.
// STRATA_BENCH_PGM=reduced runs a subset with fewer frames, for llvmpipe; unset, the full set.
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

// The first frames compile programs on use, and PGM's primary sphere comes from the previous frame's
// heights (visible_radius.hpp), so a frame is typical only after a few.
constexpr int kWarmUpFrames = 4;

struct Size {
  int width, height;
  std::string text() const { return std::to_string(width) + "x" + std::to_string(height); }
};

// The thesis's Tables 6.2 to 6.4 vary grid and screen over these; Table 6.5 sets grid = screen at these.
const std::vector<Size> kThesisSizes = {{256, 256}, {256, 512}, {512, 512}, {512, 1024}, {1024, 1024}};
const std::vector<Size> kStandardResolutions = {{640, 480}, {1024, 768}, {1280, 800}, {1920, 1200}};

// Test case 1 (Fig. 6.1): the whole planet, straight down from 8,000 km. Test case 2 (Fig. 6.2): near the
// planet at a steep angle, 20 km up, tilted 70 degrees toward the horizon.
strata::Camera testCaseCamera(int testCase) {
  return testCase == 1 ? strata::bench::wholeMarsView() : strata::bench::nearMarsView();
}

// One configuration: the pipeline loaded once with the grid, warmed up, then one frame per iteration,
// waited for with glFinish so that the wall time holds the GPU's work. Counters are means per frame.
void benchmarkPgm(benchmark::State& state, const fs::path& pipeline, int testCase, Size grid, Size screen) {
  strata::Engine engine;
  engine.load(pipeline, {"nodes.terrain.grid=" + grid.text()});
  engine.camera() = testCaseCamera(testCase);
  strata::bench::warmUp(engine, screen.width, screen.height, kWarmUpFrames);
  double pgmMs = 0, rasterMs = 0, frameMs = 0;
  for (auto _ : state) {
    frameMs += strata::bench::timedFrameMs(engine, screen.width, screen.height);
    const strata::GeometryStatistics geometry = engine.geometryStatistics();
    pgmMs += geometry.subdivisionMs, rasterMs += geometry.rasterisationMs;
  }
  strata::bench::setMeans(state, {{"pgm_ms", pgmMs}, {"raster_ms", rasterMs}, {"frame_ms", frameMs}});
  state.counters["grid_points"] = double(grid.width) * double(grid.height);
}

struct Configuration {
  std::string name;
  int testCase;
  Size grid, screen;
};

// Every grid against every screen (Tables 6.2, 6.3), then grid = screen (Table 6.5), for one test case.
std::vector<Configuration> thesisTables(int testCase, const std::vector<Size>& grids, const std::vector<Size>& screens,
                                        const std::vector<Size>& gridIsScreen) {
  const std::string prefix = "case:" + std::to_string(testCase);
  std::vector<Configuration> configurations;
  for (Size grid : grids)
    for (Size screen : screens)
      configurations.push_back(
          {"pgm/" + prefix + "/grid:" + grid.text() + "/screen:" + screen.text(), testCase, grid, screen});
  for (Size size : gridIsScreen)
    configurations.push_back({"pgm_grid_is_screen/" + prefix + "/" + size.text(), testCase, size, size});
  return configurations;
}

// The full set is the thesis's, both cases, 300 frames each (it averaged 10,000; 300 keep all 58 within
// minutes on a GPU). The reduced one is for llvmpipe, where a frame takes up to seconds: case 2's
// grid-by-screen table is left out (case 1's shows the shape) and each configuration times 4 frames, under
// 3 minutes on 2 cores.
void registerBenchmarks(const fs::path& pipeline) {
  const bool reduced = strata::bench::reducedRun("STRATA_BENCH_PGM");
  std::vector<Configuration> configurations = thesisTables(1, kThesisSizes, kThesisSizes, kStandardResolutions);
  const std::vector<Configuration> nearView =
      thesisTables(2, reduced ? std::vector<Size>{} : kThesisSizes, kThesisSizes, kStandardResolutions);
  configurations.insert(configurations.end(), nearView.begin(), nearView.end());
  for (const Configuration& c : configurations)
    strata::bench::registerFrames(c.name, reduced ? 4 : 300, benchmarkPgm, pipeline, c.testCase, c.grid, c.screen);
}

}  // namespace

int main(int argc, char** argv) {
  return strata::bench::runHeadless(argc, argv, [] {
    registerBenchmarks(strata::bench::writeProceduralMarsPipeline("strata-bench-pgm", "geometry.pgm"));
  });
}
