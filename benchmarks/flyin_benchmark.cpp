// The fly-in of seed 000 (section 5.1): from a whole-planet view down to a close-up of a mountain and
// back, frame by frame as a viewer would draw it (issue 4, docs/benchmarks.md). The planet is
// source.procedural's on a Mars-sized body, unexaggerated; the mountain is the highest point of a 1-degree
// survey of its heights, and the flight ends 300 m above that summit, tilted toward it.
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

#include <planet_model.hpp>
#include <strata/engine.hpp>
#include <strata/gl.hpp>
#include <strata/gl/context.hpp>

namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kFramesEachWay = 150;  // 5 s down and 5 s up at 30 Hz
constexpr double kMarsRadius = 3396190.0, kStartAltitude = 1.0e7, kAboveSummit = 300.0;

struct Summit {
  double lon = 0.0, lat = 0.0;  // deg
  double height = 0.0;          // m
};

// The highest of a 1-degree grid of the model's heights.
Summit highestPoint() {
  const strata::procedural::PlanetModel model({}, kMarsRadius);
  Summit best{0.0, 0.0, -1e9};
  for (int lat = -80; lat <= 80; ++lat)
    for (int lon = -180; lon < 180; ++lon) {
      const double h = model.height(strata::unitNormal(glm::radians(double(lon)), glm::radians(double(lat))));
      if (h > best.height) best = {double(lon), double(lat), h};
    }
  return best;
}

fs::path writePipeline() {
  const fs::path file = fs::temp_directory_path() / "strata-bench-flyin.yaml";
  std::ofstream(file) << "strata: 1\n"
                         "body: {name: Mars, radius: " << kMarsRadius << "}\n"
                         "nodes:\n"
                         "  colours: {type: source.procedural, kind: color}\n"
                         "  relief: {type: source.procedural, kind: height}\n"
                         "  terrain: {type: geometry.icosahedral, height: relief, lowest: -12000, highest: 12000}\n"
                         "  frame: {type: output.image, geometry: terrain, surface: [colours]}\n";
  return file;
}

// Camera at step `i` of the flight: altitude falls geometrically to 300 m above the summit, starting
// 2 km south of it and looking north, tilting from straight down to 75 degrees below 100 km.
strata::Camera cameraAt(int i, const Summit& summit) {
  const int step = i < kFramesEachWay ? i : 2 * kFramesEachWay - 1 - i;
  const double t = double(step) / double(kFramesEachWay - 1);
  const double low = summit.height + kAboveSummit;
  const double altitude = kStartAltitude * std::pow(low / kStartAltitude, t);
  const double closeness = std::clamp(std::log10(1.0e5 / altitude) / std::log10(1.0e5 / low), 0.0, 1.0);
  return {.lon = summit.lon, .lat = summit.lat - glm::degrees(2000.0 / kMarsRadius) * closeness,
          .altitude = altitude, .heading = 0.0, .tilt = 75.0 * closeness, .fov = 45.0};
}

double percentile(std::vector<double> values, double fraction) {
  std::ranges::sort(values);
  return values[std::min(values.size() - 1, std::size_t(fraction * double(values.size())))];
}

void BM_FlyIn(benchmark::State& state) {
  auto context = strata::createHeadlessContext(false);
  strata::Engine engine;
  engine.load(writePipeline());
  const Summit summit = highestPoint();
  std::vector<double> frameMs;
  double patches = 0, triangles = 0, visibility = 0, subdivision = 0, rasterisation = 0;
  for (auto _ : state) {
    for (int i = 0; i < 2 * kFramesEachWay; ++i) {
      engine.camera() = cameraAt(i, summit);
      const auto start = std::chrono::steady_clock::now();
      engine.render(kWidth, kHeight);
      glFinish();
      frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
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
  std::printf("summit %.0f m at %.0f, %.0f; %s\n", summit.height, summit.lon, summit.lat,
              strata::currentGlInfo().renderer.c_str());
}

BENCHMARK(BM_FlyIn)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
