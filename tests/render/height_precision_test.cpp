// Issue 27: heights are sampled relative to the point below the eye, as colours are. A DEM strip of 25 cm
// texels (512 m by 128 m of an analytic surface, a sum of sines of metre amplitude) at lon 137.4, lat -4.6
// on a Mars-radius body is seen from 10 m up, straight down and tilted, by each generator. Along every
// judged pixel's ray the rendered surface (the geometry's depth, read back) must lie within 1 cm of the
// analytic one (a ray cast in double), and no pixel whose ray meets the strip may show the background.
//
// The 1 cm holds with room: the DEM's bilinear interpolation departs from the sines by at most
// curvature x texel^2 / 8 = 0.19 x 0.25^2 / 8 = 1.5 mm, and float depth resolves 10 m to a micrometre. What is
// judged is precision, not the level of detail: each generator takes a pixel error of 0.1 (4 mm at 10 m), since
// the default's pixel is 3.7 cm, and once the DEM's curvature let the vertices lie as far apart as it allows, the
// surface seen 45 degrees from the ground stood up to 1.2 cm off.
// A pixel is judged where its ray meets the strip at least 2 m inside its edges (beyond, the mesh blends
// into the bare sphere outside) and its four diagonal neighbours' analytic distances lie within 25 cm of
// its own (not on a ridge that hides what lies behind, where a pixel may show either side). Sampled
// through absolute float longitude and latitude (the path before issue 27), the surface stood 25 cm off.
//
// The same strip raised 3 km (a plateau: the source's `offset`), seen from 10 m above it, straight down and
// tilted, must be as exact: the generators measure their detail from the ground the height layer's range
// allows nearest the eye, not from the sphere 3 km below, which gave the heights' filtering the detail of a
// view from 3 km (geometry.healpix was 3 cm off), and geometry.icosahedral's patches are measured on their own
// heights (RegionalValueLayer::valuesWithin; measured on the sphere they stood 82 cm off straight down, 2.2 m tilted),
// also where the strip lies in a raster too large to count when opened, from the ranges `strata tile` stored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <glm/gtc/constants.hpp>

#include <strata/host/tiling.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/output.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 192;
constexpr double kMars = 3389500.0;          // m
constexpr double kLon = 137.4, kLat = -4.6;  // deg: the strip's centre, Gale crater's place
constexpr double kTexel = 0.25;              // m
constexpr int kColumns = 2048, kRows = 512;  // east, north
constexpr double kAmplitude = 2.0;           // m: the sines' amplitudes sum to this
constexpr double kMargin = 2.0;              // m inside the strip's edges
constexpr double kTolerance = 0.01;          // m along the ray
constexpr float kNoData = -32768.0f;
// Texels of no data around the strip in the large raster: 5,120 x 3,584, 18 million texels.
constexpr int kAroundLargeStrip = 1536;

// The analytic surface at metres east and north of the strip's centre.
double analyticHeight(double east, double north) {
  const double tau = glm::two_pi<double>();
  return 1.0 * std::sin(tau * east / 23.0 + 0.3) + 0.6 * std::sin(tau * north / 17.0 + 1.1) +
         0.4 * std::sin(tau * (east + north) / 31.0);
}

// Metres east and north of the centre, measured along the sphere as the raster's texels are laid.
glm::dvec2 metresFromCentre(double lon, double lat) {
  const double east = std::remainder(lon - kLon, 360.0);
  return {glm::radians(east) * kMars * std::cos(glm::radians(kLat)), glm::radians(lat - kLat) * kMars};
}

std::array<double, 4> stripExtent() {
  const double lonSpan = glm::degrees(kTexel * kColumns / (kMars * std::cos(glm::radians(kLat))));
  const double latSpan = glm::degrees(kTexel * kRows / kMars);
  return {kLon - lonSpan / 2, kLat - latSpan / 2, kLon + lonSpan / 2, kLat + latSpan / 2};
}

bool insideStrip(glm::dvec2 metres) {
  return std::abs(metres.x) < kTexel * kColumns / 2 - kMargin && std::abs(metres.y) < kTexel * kRows / 2 - kMargin;
}

// The terrain the ray cast meets: the sines raised by `plateau` over the strip, the bare sphere elsewhere.
std::function<double(double, double)> terrainHeight(double plateau) {
  return [plateau](double lon, double lat) {
    const glm::dvec2 metres = metresFromCentre(lon, lat);
    return insideStrip(metres) ? plateau + analyticHeight(metres.x, metres.y) : 0.0;
  };
}

// The strip alone, or with `around` texels of no data on every side.
std::string writeStrip(const TemporaryDirectory& directory, int around) {
  const std::array<double, 4> strip = stripExtent();
  const double lonStep = (strip[2] - strip[0]) / kColumns, latStep = (strip[3] - strip[1]) / kRows;
  const std::array<double, 4> extent{strip[0] - around * lonStep, strip[1] - around * latStep,
                                     strip[2] + around * lonStep, strip[3] + around * latStep};
  writeFloatRaster(
      directory.path() / "strip.tif", kColumns + 2 * around, kRows + 2 * around, extent,
      [&](int column, int row) {
        if (column < around || column >= around + kColumns || row < around || row >= around + kRows) return kNoData;
        const glm::dvec2 metres =
            metresFromCentre(extent[0] + (column + 0.5) * lonStep, extent[3] - (row + 0.5) * latStep);
        return float(analyticHeight(metres.x, metres.y));
      },
      kNoData);
  return "strip.tif";
}

// The strip amid no data in a raster too large for source.gdal to count its blocks when opening it
// (more than 16 million texels), tiled by `strata tile`, which stores them.
std::string writeTiledStrip(const TemporaryDirectory& directory, const PluginRegistry& plugins) {
  writeStrip(directory, kAroundLargeStrip);
  tileRaster(plugins, {.input = directory.path() / "strip.tif", .output = directory.path() / "tiled.tif"});
  return "tiled.tif";
}

struct Errors {
  int judged = 0;
  int holes = 0;       // the ray meets the strip, and nothing was drawn
  double worst = 0.0;  // m along the ray
};

Errors measure(const View& view, const std::vector<float>& depth, double plateau) {
  const auto terrain = terrainHeight(plateau);
  const double highest = plateau + kAmplitude;
  Errors errors;
  for (int y = 1; y < kSize - 1; ++y)
    for (int x = 1; x < kSize - 1; ++x) {
      const auto hit = raycastTerrain(view, kMars, terrain, highest, 0.05, x, y);
      if (!hit || !insideStrip(metresFromCentre(hit->lon, hit->lat))) continue;
      bool smooth = true;
      for (const int dx : {-1, 1})
        for (const int dy : {-1, 1}) {
          const auto beside = raycastTerrain(view, kMars, terrain, highest, 0.05, x + dx, y + dy);
          smooth = smooth && beside && std::abs(beside->distance - hit->distance) < 0.25;
        }
      const float drawn = depth[static_cast<std::size_t>(y) * kSize + x];
      if (drawn <= 0.0f) ++errors.holes;
      if (!smooth || drawn <= 0.0f) continue;
      ++errors.judged;
      errors.worst = std::max(errors.worst, std::abs(rayDistance(view, drawn, x, y) - hit->distance));
    }
  return errors;
}

// The detail each generator is asked for: a pixel error of 0.1 where the generator measures one. geometry.clipmap
// measures none: its rings lie apart by a share of their distance from the eye ([Clasen & Hege 2006, §3.4]), which
// 60 rings a level and 1024 steps make 1.2% radially and 0.6% across (its defaults' 3.4% and 1.2% left the surface
// seen at 45 degrees 3.3 cm off along the ray; these, 4.3 mm).
std::string finerDetail(const std::string& geometry) {
  return geometry == "geometry.clipmap" ? ", rings: 60, steps: 1024" : ", pixel_error: 0.1";
}

// Tilt (deg), plateau (m), and whether the strip lies in a large tiled raster.
using Setting = std::tuple<double, double, bool>;
class HeightPrecision : public ::testing::TestWithParam<std::tuple<std::string, Setting>> {};

TEST_P(HeightPrecision, QuarterMetreDemLiesWithinOneCentimetreFromTenMetres) {
  const auto& [geometry, setting] = GetParam();
  const auto& [tilt, plateau, large] = setting;
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const std::string strip = large ? writeTiledStrip(directory, engine->plugins()) : writeStrip(directory, 0);
  const auto pipeline =
      directory.write("strip.yaml",
                      "strata: 1\nbody: {name: Mars, radius: 3389500}\n"
                      "camera: {lon: 137.40002, lat: -4.60001, altitude: " +
                          std::to_string(plateau + 10.0) + ", heading: 30, tilt: " + std::to_string(tilt) +
                          ", fov: 40}\nnodes:\n"
                          "  strip: {type: source.gdal, path: " +
                          strip + ", kind: height, offset: " + std::to_string(plateau) +
                          "}\n"
                          "  terrain: {type: " +
                          geometry + ", height: strip" + finerDetail(geometry) +
                          "}\n"
                          "  frame: {type: output.image, geometry: terrain, shading: none, antialiasing: none}\n");
  engine->load(pipeline);
  const FrameOutput& output = engine->renderComplete(kSize, kSize);
  ASSERT_NE(output.surface(), nullptr);
  const View view = engine->view(kSize, kSize);
  const Errors errors = measure(view, readDepth(output.surface()->gbuffer()), plateau);
  std::printf("%s tilt %.0f, plateau %.0f m: %d pixels judged, worst %.4f m along the ray, %d holes\n",
              geometry.c_str(), tilt, plateau, errors.judged, errors.worst, errors.holes);
  EXPECT_GT(errors.judged, kSize * kSize / 2);
  EXPECT_LE(errors.worst, kTolerance);
  EXPECT_EQ(errors.holes, 0);
}

std::string nameOf(const ::testing::TestParamInfo<std::tuple<std::string, Setting>>& param) {
  const std::string& type = std::get<0>(param.param);
  const Setting& setting = std::get<1>(param.param);
  return type.substr(type.find('.') + 1) + "_tilt" + std::to_string(int(std::get<0>(setting))) +
         (std::get<1>(setting) > 0.0 ? "_plateau" : "") + (std::get<2>(setting) ? "_tiled" : "");
}

INSTANTIATE_TEST_SUITE_P(GeneratorsAndTilts, HeightPrecision,
                         ::testing::Combine(::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(Setting(0.0, 0.0, false), Setting(45.0, 0.0, false))),
                         nameOf);
INSTANTIATE_TEST_SUITE_P(GeneratorsOverAPlateau, HeightPrecision,
                         ::testing::Combine(::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(Setting(0.0, 3000.0, false),
                                                              Setting(45.0, 3000.0, false))),
                         nameOf);
// Heights region by region from the ranges `strata tile` stored: without them the icosahedral tree measured
// the plateau's patches on the sphere, 3 km below, and the surface stood 82 cm off.
INSTANTIATE_TEST_SUITE_P(GeneratorsOverAPlateauTiled, HeightPrecision,
                         ::testing::Combine(::testing::Values("geometry.icosahedral", "geometry.healpix",
                                                              "geometry.clipmap"),
                                            ::testing::Values(Setting(0.0, 3000.0, true))),
                         nameOf);

}  // namespace
}  // namespace strata::test
