// A projection a third party adds through the SDK (ProjectionDeclaration with its own GLSL) is recognised
// from a raster's CRS and sampled like the built-in ones: a checkerboard drawn in spherical Mercator, a
// projection Strata does not ship, lands on the globe where the analytic ray-sphere intersection says.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include <strata/plugin/plugin_registry.hpp>

#include "board_judging.hpp"
#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 6371000.0;

// Spherical Mercator (Snyder 1987, eqs. 7-1, 7-2 and 7-4), as a plugin would write it.
class Mercator : public Projection {
 public:
  explicit Mercator(double radius) : radius_(radius) {}
  std::string type() const override { return "test-mercator"; }
  std::string projString() const override { return "+proj=merc +R=" + std::to_string(radius_); }
  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (std::abs(lonlat.y) >= kPi / 2) return std::nullopt;
    return glm::dvec2(radius_ * std::remainder(lonlat.x, 2 * kPi),
                      radius_ * std::log(std::tan(kPi / 4 + lonlat.y / 2)));
  }
  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    return glm::dvec2(xy.x / radius_, kPi / 2 - 2 * std::atan(std::exp(-xy.y / radius_)));
  }
  std::optional<double> periodX() const override { return 2 * kPi * radius_; }
  std::string glslInclude() const override { return "test/mercator.glsl"; }
  std::string glslFunction() const override { return "testMercator"; }
  std::array<glm::dvec4, 2> glslParameters() const override { return {}; }
  double glslMapScale() const override { return radius_; }

 private:
  double radius_;
};

ProjectionDeclaration mercatorDeclaration() {
  return {"test-mercator",
          "spherical Mercator, registered by a test as a plugin would",
          {"merc"},
          [](const ProjParameters&, const Ellipsoid& ellipsoid) -> std::unique_ptr<Projection> {
            return std::make_unique<Mercator>(ellipsoid.semiMajorAxis);
          },
          {{"test/mercator.glsl",
            "#include \"strata/constants.glsl\"\n"
            "vec3 testMercator(vec2 lonlat, vec4 a, vec4 b) {\n"
            "  float lon = lonlat.x - TWO_PI * floor((lonlat.x + PI) / TWO_PI);\n"
            "  return vec3(lon, log(tan(0.25 * PI + 0.5 * lonlat.y)), 1.0);\n"
            "}\n"}}};
}

// Writes an RGB GeoTIFF in the test's spherical Mercator, `size` texels a side placed by `transform`, with
// colour(x, y) per texel.
void writeMercatorRaster(const std::filesystem::path& file, int size, const std::array<double, 6>& transform,
                         const std::function<Rgb8(int x, int y)>& colour) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(
      GetGDALDriverManager()->GetDriverByName("GTiff")->Create(file.c_str(), size, size, 3, GDT_Byte, nullptr));
  OGRSpatialReference crs;
  crs.SetFromUserInput(("+proj=merc +R=" + std::to_string(kRadius) + " +units=m").c_str());
  dataset->SetSpatialRef(&crs);
  std::array<double, 6> geotransform = transform;
  dataset->SetGeoTransform(geotransform.data());
  std::vector<unsigned char> rgb(std::size_t(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Rgb8 texel = colour(x, y);
      for (int c = 0; c < 3; ++c) rgb[(std::size_t(y) * size + x) * 3 + c] = texel[c];
    }
  ASSERT_EQ(dataset->RasterIO(GF_Write, 0, 0, size, size, rgb.data(), size, size, GDT_Byte, 3, nullptr, 3, size * 3, 1),
            CE_None);
}

// Cells of 45 degrees, as in the surface colour test, drawn into a Mercator raster to latitude 80.
void writeMercatorCheckerboard(const std::filesystem::path& file) {
  const int size = 512;
  const double top = kRadius * std::log(std::tan(kPi / 4 + 80.0 * kPi / 360.0));
  const std::array<double, 6> transform{-kPi * kRadius, 2 * kPi * kRadius / size, 0, top, 0, -2 * top / size};
  const Mercator mercator(kRadius);
  writeMercatorRaster(file, size, transform, [&](int x, int y) {
    const glm::dvec2 lonlat =
        *mercator.inverse({transform[0] + (x + 0.5) * transform[1], top + (y + 0.5) * transform[5]});
    return cellColour(int(std::floor((lonlat.x * 180 / kPi + 180.0) / 45.0)) % 8,
                      int(std::floor((90.0 - lonlat.y * 180 / kPi) / 45.0)));
  });
}

double distanceToCellEdge(double degrees) { return std::abs(degrees - 45.0 * std::round(degrees / 45.0)); }

TEST(PluginProjection, ARasterInAPluginsProjectionLandsWhereItBelongs) {
  TemporaryDirectory directory;
  writeMercatorCheckerboard(directory.path() / "cells.tif");
  auto engine = makeEngine();
  engine->plugins().addProjection(mercatorDeclaration());
  auto pipeline =
      directory.write("mercator.yaml",
                      "strata: 1\ncamera: {lon: 20, lat: 30, altitude: 1.2e7}\nnodes:\n"
                      "  cells: {type: source.gdal, path: " +
                          (directory.path() / "cells.tif").string() +
                          ", kind: color}\n"
                          "  globe: {type: geometry.icosahedral}\n"
                          "  frame: {type: output.image, geometry: globe, surface: [cells], shading: none}\n");
  const Image image = renderFrame(*engine, pipeline, 320, 240);
  const View view = engine->view(320, 240);
  int judged = 0;
  for (int y = 1; y < 240; y += 3)
    for (int x = 1; x < 320; x += 3) {
      auto hit = raycastSphere(view, kRadius, x, y);
      // Away from cell edges (filtering and the mesh's chords blur them), grazing views and Mercator's
      // stretched far north and south.
      if (!hit || hit->incidence < 0.3 || std::abs(hit->lat) > 70.0) continue;
      if (distanceToCellEdge(hit->lon) < 2.0 || distanceToCellEdge(hit->lat) < 2.0) continue;
      const Rgb8 expected =
          cellColour(int(std::floor((hit->lon + 180.0) / 45.0)) % 8, int(std::floor((90.0 - hit->lat) / 45.0)));
      const auto pixel = image.at(x, y);
      ++judged;
      // 2 levels: the sRGB decode to half floats and the re-encode to 8 bits each round by under one.
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pixel[c], expected[c], 2) << x << "," << y << " lon " << hit->lon << " lat " << hit->lat;
    }
  EXPECT_GT(judged, 600) << "too few pixels were judged for the test to mean anything";
}

// A plugin's projection gets centimetre texels anywhere from its forward() alone
// (docs/sdk/writing-a-projection.md): a board of 1 cm Mercator texels in cells of 16 at Gale crater's place, seen
// from 2 m straight down and tilted 60 degrees, is as crisp as raster_precision_test.cpp's boards, judged the
// same way. Through the plugin's GLSL at absolute float longitude (the fit's reach forced to 0) all 20,046
// judged pixels were wrong straight down and 5,500 of 5,593 tilted.
class PluginProjectionPrecision : public ::testing::TestWithParam<double> {};

TEST_P(PluginProjectionPrecision, OneCentimetreTexelsInAPluginsProjectionAreCrispFromTwoMetres) {
  constexpr int kSize = 192, kTexels = 1024, kCell = 16, kLight = 231, kDark = 48;
  constexpr double kTexel = 0.01;  // m of Mercator x and y: 0.997 cm on the ground at 4.6 S
  const Mercator mercator(kRadius);
  const glm::dvec2 centre = *mercator.forward({137.4 * kPi / 180.0, -4.6 * kPi / 180.0});
  const std::array<double, 6> t{centre.x - kTexel * kTexels / 2, kTexel, 0,
                                centre.y + kTexel * kTexels / 2, 0,      -kTexel};
  TemporaryDirectory directory;
  writeMercatorRaster(directory.path() / "board.tif", kTexels, t, [](int x, int y) {
    const auto grey = static_cast<unsigned char>((x / kCell + y / kCell) % 2 == 0 ? kLight : kDark);
    return Rgb8{grey, grey, grey};
  });
  auto engine = makeEngine();
  engine->plugins().addProjection(mercatorDeclaration());
  const auto pipeline = directory.write(
      "board.yaml", "strata: 1\ncamera: {lon: 137.4000123, lat: -4.6000045, altitude: 2, heading: 30, tilt: " +
                        std::to_string(GetParam()) +
                        ", fov: 40}\nnodes:\n"
                        "  board: {type: source.gdal, path: board.tif}\n"
                        "  globe: {type: geometry.icosahedral}\n"
                        "  frame: {type: output.image, geometry: globe, surface: [board], shading: none}\n");
  const Image image = renderFrame(*engine, pipeline, kSize, kSize);
  const TexelBoard board{[&](double lon, double lat) {
                           const glm::dvec2 map = *mercator.forward({lon * kPi / 180.0, lat * kPi / 180.0});
                           return glm::dvec2((map.x - t[0]) / t[1], (map.y - t[3]) / t[5]);
                         },
                         kTexels, kTexels, kCell};
  const Judgement judgement = judgeBoard(image, engine->view(kSize, kSize), kRadius, board, false, kLight, kDark);
  EXPECT_GT(judgement.judged, kSize * kSize / 8);  // tilted, far pixels straddle the 16 cm cells: 5,593 judged
  EXPECT_EQ(judgement.wrong, 0) << "of " << judgement.judged << " pixels";
}

INSTANTIATE_TEST_SUITE_P(Tilts, PluginProjectionPrecision, ::testing::Values(0.0, 60.0),
                         [](const ::testing::TestParamInfo<double>& param) {
                           return "tilt" + std::to_string(int(param.param));
                         });

}  // namespace
}  // namespace strata::test
