// The fly-in of [Kooima 2008, §5.1]: from a whole-planet view down to a close-up of a mountain and back,
// frame by frame as a viewer would draw it (issue 4, docs/benchmarks.md). The planet is source.procedural's
// on a Mars-sized body, unexaggerated; the mountain is the highest point of a 1-degree survey of its heights,
// and the flight ends 300 m above that summit, tilted toward it. Then the cost of each extra surface layer
// (issue 7; [Kooima 2008, §5.1.4] measured about 2 ms a full-screen overlay pass at 1920x1080): one frame of
// the flight, halfway down, drawn with 0, 1, 2 and 4 raster layers more.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include <fly_in_path.hpp>
#include <planet_model.hpp>
#include <strata/gl.hpp>
#include <strata/gl/context.hpp>
#include <strata/host/engine.hpp>

#include "headless_main.hpp"
#include "procedural_mars_pipeline.hpp"

namespace {

using strata::icosahedral::FlyInPath;

constexpr int kWidth = 1280, kHeight = 720;
constexpr double kMarsRadius = FlyInPath::kMarsRadius;

// The flight to the highest of a 1-degree grid of the model's heights.
FlyInPath flightToHighestPoint() {
  const strata::procedural::PlanetModel model({}, kMarsRadius);
  FlyInPath best{0.0, 0.0, -1e9};
  for (int lat = -80; lat <= 80; ++lat)
    for (int lon = -180; lon < 180; ++lon) {
      const double h = model.height(strata::unitNormal(glm::radians(double(lon)), glm::radians(double(lat))));
      if (h > best.summitHeight) best = {double(lon), double(lat), h};
    }
  return best;
}

double percentile(std::vector<double> values, double fraction) {
  std::ranges::sort(values);
  return values[std::min(values.size() - 1, std::size_t(fraction * double(values.size())))];
}

void BM_FlyIn(benchmark::State& state) {
  auto context = strata::createHeadlessContext(false);
  strata::Engine engine;
  engine.load(strata::bench::writeProceduralMarsPipeline("strata-bench-flyin", "geometry.icosahedral"));
  const FlyInPath flight = flightToHighestPoint();
  std::vector<double> frameMs;
  double patches = 0, triangles = 0, visibility = 0, subdivision = 0, rasterisation = 0;
  for (auto _ : state) {
    for (int i = 0; i < 2 * FlyInPath::kFramesEachWay; ++i) {
      engine.camera() = flight.cameraAt(i);
      frameMs.push_back(strata::bench::timedFrameMs(engine, kWidth, kHeight));
      const strata::GeometryStatistics geometry = engine.geometryStatistics();
      patches += geometry.patches, triangles += double(geometry.triangles), visibility += geometry.visibilityMs;
      subdivision += geometry.subdivisionMs, rasterisation += geometry.rasterisationMs;
    }
  }
  const double frames = double(frameMs.size());
  state.counters["frame_ms_mean"] = std::accumulate(frameMs.begin(), frameMs.end(), 0.0) / frames;
  state.counters["frame_ms_p95"] = percentile(frameMs, 0.95);
  state.counters["frame_ms_max"] = percentile(frameMs, 1.0);
  state.counters["patches"] = patches / frames;
  state.counters["triangles"] = triangles / frames;
  state.counters["visibility_ms"] = visibility / frames;
  state.counters["subdivision_ms"] = subdivision / frames;
  state.counters["rasterisation_ms"] = rasterisation / frames;
  std::printf("summit %.0f m at %.0f, %.0f; %s\n", flight.summitHeight, flight.summitLon, flight.summitLat,
              strata::currentGlInfo().renderer.c_str());
}

BENCHMARK(BM_FlyIn)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// The fly-in's pipeline with `extra` colour layers more over the procedural planet's, each a paged raster (the
// demo's 2048x1024 Earth image, taken as global) read through its own node, blended per pixel by coverage.
std::filesystem::path pipelineWithExtraLayers(int extra) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("strata-bench-flyin-layers-" + std::to_string(extra) + ".yaml");
  std::ofstream out(file);
  out << "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
         "  colours: {type: source.procedural, kind: color}\n"
         "  relief: {type: source.procedural, kind: height}\n"
         "  terrain: {type: geometry.icosahedral, height: relief, lowest: -12000, highest: 12000}\n";
  std::string surface = "colours";
  for (int i = 0; i < extra; ++i) {
    out << "  image" << i << ": {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg}\n";
    surface += ", image" + std::to_string(i);
  }
  out << "  frame: {type: output.image, geometry: terrain, surface: [" << surface << "]}\n";
  return file;
}

void BM_ExtraLayers(benchmark::State& state) {
  auto context = strata::createHeadlessContext(false);
  strata::Engine engine;
  engine.load(pipelineWithExtraLayers(int(state.range(0))));
  engine.camera() = flightToHighestPoint().cameraAt(FlyInPath::kFramesEachWay / 2);
  engine.renderComplete(kWidth, kHeight);  // every page of every layer loaded, programs compiled
  double frameMs = 0.0;
  for (auto _ : state) {
    frameMs += strata::bench::timedFrameMs(engine, kWidth, kHeight);
  }
  state.counters["frame_ms"] = frameMs / double(state.iterations());
}

BENCHMARK(BM_ExtraLayers)
    ->ArgName("extra_layers")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(10);

}  // namespace

BENCHMARK_MAIN();
