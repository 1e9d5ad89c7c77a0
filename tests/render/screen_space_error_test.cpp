// The level of detail by screen-space error (patch_tree.hpp) draws what a much finer threshold draws: a real
// global image (xplanet's Blue Marble) on the bare Earth, rendered with the default pixel error and with
// one twenty times finer (capped at 20,000 patches rather than 300), from the peer benchmark's whole-Earth
// view and from a tilted view across the antimeridian near the pole, where longitude bends fastest.
//
// The surface is textured per pixel from the longitude and latitude the mesh interpolates (deferred texturing),
// so what differs is where the coarser chords put the ground and how they bend the interpolated coordinates:
// both under a pixel by construction. Measured on llvmpipe: mean differences of 0.146 and 0.138 levels, 0.009%
// and 0.031% of the pixels differing by more than 16; for scale, each default image against itself shifted one
// pixel sideways differs by 5.3 and 1.6 levels, 12% and 2.3% by more than 16. Tolerances: a mean under 1 level and
// under 0.5% of the pixels differing by more than 16 levels, and a mean under a quarter of the one-pixel shift's: the
// default draws the ground well within a pixel of where the finer threshold does.
//
// The same on terrain whose blocks show it smooth (EGM96's geoid x1000: patch_tree.hpp's roughness, and its texels'
// curvature), from 3,000 km tilted 45 degrees, against a threshold a fifth of the default's: measured with
// geometry.icosahedral, a mean of 0.392 levels and 0.051% by more than 16 (0.160 and 0.016% by the relief alone,
// which took more patches), the image shifted a pixel 2.8 levels and 3.7%.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "image_agreement.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 640, kHeight = 360;
constexpr double kMeanTolerance = 1.0;     // levels
constexpr double kLargeTolerance = 0.005;  // of the pixels compared

// The image moved one pixel to the right, its first column repeated.
Image shiftedRight(const Image& image) {
  Image shifted = image;
  for (int y = 0; y < image.height; ++y)
    for (int x = 1; x < image.width; ++x)
      for (int c = 0; c < 4; ++c)
        shifted.rgba[std::size_t((y * image.width + x) * 4 + c)] =
            image.rgba[std::size_t((y * image.width + x - 1) * 4 + c)];
  return shifted;
}

// The generator under test and the parameters that make its threshold much finer than the default's.
struct Generator {
  std::string type;
  std::string finer;  // appended to the node's parameters
};

std::string blueMarble(const Generator& generator, const std::string& geometryParameters) {
  return "strata: 1\nnodes:\n"
         "  imagery: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, kind: color}\n"
         "  globe: {type: " +
         generator.type + geometryParameters +
         "}\n"
         "  frame: {type: output.image, geometry: globe, surface: [imagery], shading: none}\n";
}

// The Blue Marble on EGM96's geoid exaggerated 1000 times (+-100 km), shaded by the geometry's normals.
std::string blueMarbleOnTheGeoid(const Generator& generator, const std::string& geometryParameters) {
  return "strata: 1\nnodes:\n"
         "  imagery: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, kind: color}\n"
         "  geoid: {type: source.gdal, path: /usr/share/proj/egm96_15.gtx, kind: height, scale: 1000}\n"
         "  globe: {type: " +
         generator.type + ", height: geoid" + geometryParameters +
         "}\n"
         "  frame: {type: output.image, geometry: globe, surface: [imagery]}\n";
}

void expectAgreement(const Image& byDefault, const Image& fine, const Camera& camera) {
  const ImageAgreement agreement = agreementAwayFromSilhouettes(byDefault, fine);
  const ImageAgreement shift = agreementAwayFromSilhouettes(byDefault, shiftedRight(byDefault));
  std::printf(
      "lon %.0f lat %.0f, %.0f m up: %d pixels compared, mean difference %.3f levels, %.3f%% differ by "
      "more than %d; shifted a pixel: %.3f levels, %.3f%%\n",
      camera.lon, camera.lat, camera.altitude, agreement.compared, agreement.meanDifference,
      100.0 * agreement.largeShare, kLargeDifference, shift.meanDifference, 100.0 * shift.largeShare);
  EXPECT_LT(agreement.meanDifference, shift.meanDifference / 4.0);
  EXPECT_GT(agreement.compared, kWidth * kHeight / 10);
  EXPECT_LT(agreement.meanDifference, kMeanTolerance);
  EXPECT_LT(agreement.largeShare, kLargeTolerance);
}

class ScreenSpaceError : public ::testing::TestWithParam<Generator> {};

TEST_P(ScreenSpaceError, TheDefaultThresholdDrawsWhatAFinerOneDraws) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  for (const Camera& camera :
       {Camera{.lon = 10, .lat = 20, .altitude = 2.0e7, .fov = 36},
        Camera{.lon = 179, .lat = 70, .altitude = 2.0e6, .heading = 30, .tilt = 30, .fov = 36}}) {
    engine->load(directory.write("default.yaml", blueMarble(GetParam(), "")));
    const Image byDefault = renderFrames(*engine, camera, kWidth, kHeight, 1);
    engine->load(directory.write("fine.yaml", blueMarble(GetParam(), ", pixel_error: 0.05" + GetParam().finer)));
    expectAgreement(byDefault, renderFrames(*engine, camera, kWidth, kHeight, 1), camera);
  }
}

TEST_P(ScreenSpaceError, OnSmoothTerrainTheDefaultThresholdDrawsWhatAFinerOneDraws) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const Camera camera{.lon = 10, .lat = 20, .altitude = 3e6, .tilt = 45, .fov = 36};
  engine->load(directory.write("default.yaml", blueMarbleOnTheGeoid(GetParam(), "")));
  const Image byDefault = renderFrames(*engine, camera, kWidth, kHeight, 1);
  engine->load(directory.write("fine.yaml", blueMarbleOnTheGeoid(GetParam(), ", pixel_error: 0.2" + GetParam().finer)));
  expectAgreement(byDefault, renderFrames(*engine, camera, kWidth, kHeight, 1), camera);
}

// The geoid read whole by source.gdal knows its texels' curvature (BlockRelief), so that linear interpolation's
// second-order error, not its relief, sets the vertex spacing: EGM96 x1000 from 2,000 km straight down,
// 1280 x 720, takes under half the 300 patches it took by its relief alone (measured: 279 by relief, 110 with the
// curvature), and still draws what a threshold five times finer draws (OnSmoothTerrain above).
TEST(ScreenSpaceErrorOnTheGeoid, TheTexelsCurvatureSparesPatches) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  engine->load(directory.write("geoid.yaml", blueMarbleOnTheGeoid({"geometry.icosahedral", ""}, "")));
  renderFrames(*engine, Camera{.lon = 10, .lat = 20, .altitude = 2.0e6, .fov = 36}, 1280, 720, 1);
  const int patches = engine->geometryStatistics().patches;
  std::printf("the geoid x1000 from 2,000 km: %d patches\n", patches);
  EXPECT_LT(patches, 150);
}

// geometry.icosahedral's finer threshold may take up to 20,000 patches rather than 300; geometry.healpix's asks
// for five times the paper's recommended density as well; geometry.pgm's casts up to its whole grid.
INSTANTIATE_TEST_SUITE_P(Generators, ScreenSpaceError,
                         ::testing::Values(Generator{"geometry.icosahedral", ", patches: 20000"},
                                           Generator{"geometry.healpix", ", threshold: 1.0"},
                                           Generator{"geometry.pgm", ""}),
                         [](const ::testing::TestParamInfo<Generator>& generator) {
                           return generator.param.type.substr(generator.param.type.find('.') + 1);
                         });

}  // namespace
}  // namespace strata::test
