// composite.relief anywhere on the body ([Kooima 2008, §1.1], relief shading): the shade of a cone on the sphere
// against the analytic Lambert shading of its exact normal, far from longitude 0, across the antimeridian and
// about a pole, where a raster's texels land turned and stretched and the slopes must be turned back along the
// ground (source.gdal's heights give their slopes with their value: SlopedLayer).
//
// The cone: height H (1 - d / D) within great-circle distance d < D of its apex, on Mars, H = 20 km, D = 1 degree
// (59.3 km), so its flank rises at H / D = 0.337 (18.6 degrees) everywhere, facing away from the apex; a Float32
// longitude/latitude raster about the apex, of texels some 140 m to 280 m across, each the cone's height at its
// centre. Seen straight down from 160 km (a pixel some 0.5 km, 2 to 4 texels), each pixel's value is the shade
// where the exact ray-sphere intersection (in double) lands, judged between 0.2 D and 0.8 D from the apex, as
// relief_test.cpp judges its cone at (0, 0); the same tolerance, 1 level of the sRGB frame, for the same reasons
// (quantisation 0.5; the gradient of central differences mixed across a cell, second order in a texel; float
// heights). The exact normal is normalize(s away, 1) in east/north/up, `away` the unit direction away from the
// apex along the great circle, s = H / D. Measured on llvmpipe: 0.50 levels at most at Gale and across the
// antimeridian (a mean of 0.24), 0.21 about the pole (its flank faces the pole everywhere, one shade), 0.79 beside
// no data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 240;
constexpr double kRadius = 3396190.0;  // m, Mars
constexpr double kConeHeight = 20000.0;
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kConeReach = 1.0 * kDegree;  // rad of great circle
constexpr double kSlope = kConeHeight / (kConeReach * kRadius);

struct LonLat {
  double lon, lat;  // deg
};

// Great-circle distance (rad) and the bearing (rad clockwise from north) from `from` toward `to`.
double distanceBetween(LonLat from, LonLat to) {
  const double dLat = (to.lat - from.lat) * kDegree, dLon = (to.lon - from.lon) * kDegree;
  const double a = std::pow(std::sin(0.5 * dLat), 2) +
                   std::cos(from.lat * kDegree) * std::cos(to.lat * kDegree) * std::pow(std::sin(0.5 * dLon), 2);
  return 2.0 * std::asin(std::min(1.0, std::sqrt(a)));
}
double bearingToward(LonLat from, LonLat to) {
  const double dLon = (to.lon - from.lon) * kDegree, fromLat = from.lat * kDegree, toLat = to.lat * kDegree;
  return std::atan2(std::sin(dLon) * std::cos(toLat),
                    std::cos(fromLat) * std::sin(toLat) - std::sin(fromLat) * std::cos(toLat) * std::cos(dLon));
}

double coneHeight(LonLat apex, LonLat at) {
  return kConeHeight * std::max(0.0, 1.0 - distanceBetween(apex, at) / kConeReach);
}

// Lambert's cosine of the flank's exact normal at `at` under a light from azimuth 315, altitude 45 degrees.
double analyticShade(LonLat apex, LonLat at) {
  const double toward = bearingToward(at, apex);
  const double nx = -kSlope * std::sin(toward), ny = -kSlope * std::cos(toward), nz = 1.0;
  const double lx = std::sin(315.0 * kDegree) * std::cos(45.0 * kDegree),
               ly = std::cos(315.0 * kDegree) * std::cos(45.0 * kDegree), lz = std::sin(45.0 * kDegree);
  return std::max(0.0, (nx * lx + ny * ly + nz * lz) / std::sqrt(nx * nx + ny * ny + nz * nz));
}

double srgbLevel(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

// Where the cone stands and the camera looks from, with the raster about it: `columns` x `rows` texels over
// `extent` (west, south, east, north, deg).
struct Placement {
  const char* name;
  LonLat apex;
  LonLat camera;
  std::array<double, 4> extent;
  int columns, rows;
  bool westMissing = false;  // no data west of the apex: the flank beside it takes one-sided differences
};

constexpr float kNoData = -32768.0f;

class ReliefAnywhere : public ::testing::TestWithParam<Placement> {};

TEST_P(ReliefAnywhere, ShadesTheConeAsItsExactNormal) {
  const Placement& placement = GetParam();
  TemporaryDirectory directory;
  const std::filesystem::path cone = directory.path() / "cone.tif";
  const std::array<double, 4>& e = placement.extent;
  const double texelLon = (e[2] - e[0]) / placement.columns, texelLat = (e[3] - e[1]) / placement.rows;
  writeFloatRaster(
      cone, placement.columns, placement.rows, e,
      [&](int column, int row) {
        const LonLat at{e[0] + (column + 0.5) * texelLon, e[3] - (row + 0.5) * texelLat};
        return placement.westMissing && at.lon < placement.apex.lon ? kNoData : float(coneHeight(placement.apex, at));
      },
      kNoData);
  const std::string text =
      "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
      "camera: {lon: " +
      std::to_string(placement.camera.lon) + ", lat: " + std::to_string(placement.camera.lat) +
      ", altitude: 1.6e5, fov: 45}\n"
      "nodes:\n"
      "  cone: {type: source.gdal, path: " +
      cone.string() +
      ", kind: height}\n"
      "  relief: {type: composite.relief, height: cone}\n"
      "  globe: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: globe, surface: [relief], shading: none}\n";
  std::unique_ptr<Engine> engine = makeEngine();
  const Image image = renderFrame(*engine, directory.write("relief.yaml", text), kSize, kSize);
  const View view = makeView(engine->pipeline().body, engine->camera(), kSize, kSize);
  int judged = 0;
  double largest = 0.0, sum = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto hit = raycastSphere(view, kRadius, x, y);
      if (!hit) continue;
      const LonLat at{hit->lon, hit->lat};
      const double d = distanceBetween(placement.apex, at) / kConeReach;
      if (d < 0.2 || d > 0.8) continue;
      if (placement.westMissing && at.lon < placement.apex.lon) continue;
      const double error = std::abs(image.at(x, y)[0] - srgbLevel(analyticShade(placement.apex, at)));
      largest = std::max(largest, error);
      sum += error;
      ++judged;
    }
  std::printf("%s: %d pixels, largest difference %.2f levels, mean %.2f\n", placement.name, judged, largest,
              sum / std::max(judged, 1));
  EXPECT_GT(judged, placement.westMissing ? 5000 : 10000) << "the flank covers much of the frame";
  EXPECT_LE(largest, 1.0);
}

// Gale crater's place; the antimeridian through the apex (the raster's west half east of 178.6, its east half
// past 180); the north pole as the apex, under a raster of whole rows of longitude (texels 0.18 degrees of
// longitude wide, tens of metres at the judged distances, 280 m of latitude), the camera just off the pole; Gale
// again with no data west of the apex, judged up to the edge, the camera a third of a pixel west so that a column
// of pixels lies within the texel where coverage fades: their samples mix data and no data, whose slopes count by
// coverage as their values do (counted alike, zero slopes from no data, they stood 7.95 levels off).
INSTANTIATE_TEST_SUITE_P(
    Placements, ReliefAnywhere,
    ::testing::Values(
        Placement{"Gale", {137.4, -4.6}, {137.4, -4.6}, {136.2, -5.8, 138.6, -3.4}, 1024, 1024},
        Placement{"Antimeridian", {180.0, 30.0}, {180.0, 30.0}, {178.6, 28.8, 181.4, 31.2}, 1024, 1024},
        Placement{"Pole", {0.0, 90.0}, {30.0, 89.5}, {-180.0, 88.8, 180.0, 90.0}, 2048, 256},
        Placement{"BesideNoData", {137.4, -4.6}, {137.3965, -4.6}, {136.2, -5.8, 138.6, -3.4}, 1024, 1024, true}),
    [](const ::testing::TestParamInfo<Placement>& placed) { return std::string(placed.param.name); });

}  // namespace
}  // namespace strata::test
