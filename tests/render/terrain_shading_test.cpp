// The displaced terrain's shading normals, which each generator computes per vertex from its height layer (one
// sample where the layer gives its slopes with its value, SlopedLayer; central differences otherwise) and
// output.image lights (`shading: lambert`).
//
// The terrain: a plane tilted 0.2 east and -0.3 north (rise per metre along the ground), a Float32
// longitude/latitude raster of 512 x 512 texels over 0.2 x 0.2 degrees of Mars (texels some 23 m), heights up to
// 1.8 km either side of the sphere, under one grey surface; seen straight down from 20 km by each generator, at
// Gale crater's place and at lon -100, lat 75. Every pixel whose ray meets the sphere within the inner 0.12 degrees
// (the terrain's parallax, up to 0.7 km, keeps it inside the raster) must show the grey times output.image's
// light on the plane's exact normal, normalize(N - 0.2 E + 0.3 N') in the sphere's normal N, east E and north N'
// where the ray meets the sphere (the normal turns 1e-4 rad over the 0.4 km between there and the terrain's hit).
// Tolerance, 1 level of the sRGB frame: 0.5 for quantisation; a plane's slopes are exact from bilinear texels and
// central differences alike, and every vertex's normal is the same, so interpolation and geomorphing keep it; the
// raster's plane in longitude and latitude departs from a plane along the ground by the change of cos(latitude)
// across it, 0.6% of the east slope at lat 75 (0.1 level). Measured on llvmpipe: 0.23 levels at Gale, 0.21 at lat 75,
// with each generator (the plane is one shade); lit by swapped slopes it stood 38 levels off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>
#include <string>
#include <tuple>

#include <glm/glm.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 160;
constexpr double kRadius = 3396190.0;  // m, Mars
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kEastSlope = 0.2, kNorthSlope = -0.3;
constexpr double kHalfExtent = 0.1, kJudged = 0.06;  // deg
constexpr int kTexels = 512;
constexpr unsigned char kGrey = 200;  // sRGB
constexpr double kAmbient = 0.25;     // output.image's default

struct Place {
  const char* name;
  double lon, lat;  // deg
};
void PrintTo(const Place& place, std::ostream* out) { *out << place.name; }

double srgbLevel(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

// output.image's light (its default azimuth and elevation in the view) in planet-fixed axes, as it turns it.
glm::dvec3 lightOf(const View& view) {
  const double azimuth = 315.0 * kDegree, elevation = 45.0 * kDegree;  // output.image's defaults
  const glm::dvec3 inView(std::sin(azimuth) * std::cos(elevation), std::cos(azimuth) * std::cos(elevation),
                          std::sin(elevation));
  return glm::transpose(view.planetToEye) * inView;
}

// The plane's normal where the ray meets the sphere at (lon, lat), degrees.
glm::dvec3 planeNormal(double lon, double lat) {
  const double l = lon * kDegree, b = lat * kDegree;
  const glm::dvec3 up(std::cos(b) * std::cos(l), std::cos(b) * std::sin(l), std::sin(b));
  const glm::dvec3 east(-std::sin(l), std::cos(l), 0.0), north = glm::cross(up, east);
  return glm::normalize(up - kEastSlope * east - kNorthSlope * north);
}

class TerrainShading : public ::testing::TestWithParam<std::tuple<std::string, Place>> {};

TEST_P(TerrainShading, LightsThePlaneByItsExactNormal) {
  const auto& [generator, place] = GetParam();
  TemporaryDirectory directory;
  const std::array<double, 4> extent{place.lon - kHalfExtent, place.lat - kHalfExtent, place.lon + kHalfExtent,
                                     place.lat + kHalfExtent};
  const double texel = 2.0 * kHalfExtent / kTexels, metresEast = kRadius * kDegree * std::cos(place.lat * kDegree);
  writeFloatRaster(directory.path() / "plane.tif", kTexels, kTexels, extent, [&](int column, int row) {
    const double east = (-kHalfExtent + (column + 0.5) * texel) * metresEast;
    const double north = (kHalfExtent - (row + 0.5) * texel) * kRadius * kDegree;
    return float(kEastSlope * east + kNorthSlope * north);
  });
  writeColourRaster(directory.path() / "grey.tif", 8, 4, {-180, -90, 180, 90}, [](int, int) {
    return Rgb8{kGrey, kGrey, kGrey};
  });
  const std::string text =
      "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
      "camera: {lon: " +
      std::to_string(place.lon) + ", lat: " + std::to_string(place.lat) +
      ", altitude: 2.0e4, fov: 45}\n"
      "nodes:\n"
      "  plane: {type: source.gdal, path: " +
      (directory.path() / "plane.tif").string() +
      ", kind: height}\n"
      "  grey: {type: source.gdal, path: " +
      (directory.path() / "grey.tif").string() +
      ", kind: color}\n"
      "  terrain: {type: " +
      generator +
      ", height: plane}\n"
      "  frame: {type: output.image, geometry: terrain, surface: [grey]}\n";
  std::unique_ptr<Engine> engine = makeEngine();
  const Image image = renderFrame(*engine, directory.write("shading.yaml", text), kSize, kSize);
  const View view = makeView(engine->pipeline().body, engine->camera(), kSize, kSize);
  const glm::dvec3 light = lightOf(view);
  const double grey = std::pow((kGrey / 255.0 + 0.055) / 1.055, 2.4);
  int judged = 0;
  double largest = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto hit = raycastSphere(view, kRadius, x, y);
      if (!hit || std::abs(hit->lon - place.lon) > kJudged || std::abs(hit->lat - place.lat) > kJudged) continue;
      const double lit = kAmbient + (1.0 - kAmbient) * std::max(glm::dot(planeNormal(hit->lon, hit->lat), light), 0.0);
      largest = std::max(largest, std::abs(image.at(x, y)[0] - srgbLevel(grey * lit)));
      ++judged;
    }
  std::printf("%s at %s: %d pixels, largest difference %.2f levels\n", generator.c_str(), place.name, judged, largest);
  EXPECT_GT(judged, 1000) << "the plane covers much of the frame";
  EXPECT_LE(largest, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Generators, TerrainShading,
                         ::testing::Combine(::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(Place{"Gale", 137.4, -4.6},
                                                              Place{"North", -100.0, 75.0})),
                         [](const ::testing::TestParamInfo<std::tuple<std::string, Place>>& placed) {
                           const std::string& type = std::get<0>(placed.param);
                           return type.substr(type.find('.') + 1) + "_" + std::get<1>(placed.param).name;
                         });

}  // namespace
}  // namespace strata::test
