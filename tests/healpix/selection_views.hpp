#pragma once
// The views geometry.healpix's node selection is tested from, over an Earth-sized body at 1920 x 1080:
// from orbit down to 1 m, straight down and at the horizon, over the north pole where four faces meet and
// over face corners where three (lat asin(2/3), lon 0) and four (the equator at lon 45) meet.
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <strata/camera.hpp>
#include <strata/plugin/height_input.hpp>

#include "node_selection.hpp"

namespace strata::healpix {

constexpr double kEarthRadius = 6371000.0;
constexpr int kWidth = 1920, kHeight = 1080;

struct TestView {
  std::string name;
  Camera camera;
  HeightRange heights;
  View view() const { return makeView(Body{"Earth", kEarthRadius}, camera, kWidth, kHeight); }
};

inline std::vector<TestView> testViews() {
  const double threeFaces = std::asin(2.0 / 3.0) * 180.0 / 3.141592653589793;
  const HeightRange earth{-11000.0, 8900.0}, bare{0.0, 0.0};
  return {
      {"orbit 100000 km", {10.0, 20.0, 1.0e8, 0.0, 0.0, 45.0}, earth},
      {"1000 km tilted", {-30.0, 50.0, 1.0e6, 30.0, 60.0, 45.0}, earth},
      {"10 km at 45 deg", {120.0, -10.0, 1.0e4, 200.0, 45.0, 45.0}, earth},
      {"2 m over the north pole, horizon", {0.0, 90.0, 2.0, 0.0, 90.0, 45.0}, bare},
      {"2 m over 3 faces' corner, horizon", {0.0, threeFaces, 2.0, 80.0, 90.0, 45.0}, bare},
      {"2 m over 4 faces' corner, down", {45.0, 0.0, 2.0, 0.0, 0.0, 45.0}, bare},
      {"2 m in a valley (eye in the shell)", {45.0, 0.0, 2.0, 30.0, 85.0, 45.0}, {-5.0, 30.0}},
      {"1 m over the north pole, 80 deg", {10.0, 90.0, 1.0, 135.0, 80.0, 45.0}, bare},
  };
}

// Runs a selection, printing its count and time.
inline std::vector<SelectedNode> selectAndReport(const TestView& test, const SelectionSettings& settings) {
  const View view = test.view();
  const auto start = std::chrono::steady_clock::now();
  std::vector<SelectedNode> nodes = selectNodes(view, kEarthRadius, test.heights, settings);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("%-36s threshold %5.3f: %5zu nodes in %7.3f ms\n", test.name.c_str(), settings.threshold, nodes.size(),
              ms);
  return nodes;
}

}  // namespace strata::healpix
