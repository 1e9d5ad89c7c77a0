// A HEALPix pyramid (strata/plugin/healpix_pyramid.hpp) read by every generator (issue 6): heights of one smooth
// field in a global longitude/latitude raster of 4096 x 2048, and in the pyramid of nside 512 that `strata
// tile --to healpix` makes of it, give the same planet. geometry.icosahedral and geometry.pgm read the
// pyramid through the strip's projection; geometry.healpix reads it by face point, with no projection
// (HealpixFaceLayer::faceSamplingFunction), and bounds its nodes by the pyramid's page ranges
// (HealpixFaceLayer::faceNodeValues). Views: the whole planet; a face corner where three faces meet (lon 0, lat
// asin(2/3)) from 300 km and 20 km, tilted; the north pole, where four do, from 300 km: pages meet across face edges
// there. The field is exaggerated 20 times, as in generator_agreement_test.cpp, and the colour layer is the test
// checkerboard, whose cell edges show where each mesh puts the ground.
//
// Both rasters sample the field about as finely (0.088 and 0.115 degrees) and its shortest wavelength is
// over 40 degrees: the images should differ only where the meshes' vertices fall differently on the slopes,
// where the raster's coarser levels (the pyramid has one) are sampled, and near the pole, where the
// raster's texels narrow to slivers. Measured on llvmpipe, in 8-bit levels over the three channels: mean
// differences 0.01 to 0.08 levels and at most 0.01% of the pixels beyond 16, except over the pole: 0.33 to
// 0.65 levels, 0.42 to 0.90%; the outline (pixels covered in one image only) moved at no more than 6 pixels,
// all geometry.healpix's, on the limb. Tolerances: a mean of 1 level, 1.5% beyond 16, the outline moved at
// no more than 10 pixels, and no pixel emptied inside the planet, as a crack along a face edge would be:
// sampled 2^-19 of a face inside the edge, as the strip's projection does, geometry.healpix left one over
// the pole, where the field changes fastest across the faces' edges. geometry.pgm casts its whole grid: it halves
// its grid by the relief the height layer knows by region (grid_detail.hpp), which the pyramid knows by its pages
// and the raster by blocks of 8 texels: from 8,000 km the two grids (512 and 128 rays a side) drew the outline
// through different rays at the horizon, and 100 pixels along it changed sides. geometry.icosahedral likewise takes
// a pixel error of 0.05, which holds both meshes at their `patches` cap: the raster knows its texels' curvature
// (BlockRelief), the pyramid's pages do not, and at the default error the raster's smooth field took 17 to 59 patches
// where the pyramid's took 290 to 299, whose horizons, each within a pixel of the field's, moved apart at 40 pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "image_agreement.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 320, kHeight = 240;
constexpr int kNside = 512;
constexpr double kMeanTolerance = 1.0;     // levels
constexpr double kLargeTolerance = 0.015;  // of the pixels compared
constexpr int kOutlineTolerance = 10;      // pixels

// Metres, at longitude and latitude in radians.
double field(double lon, double lat) {
  return 4000.0 * std::sin(3.0 * lon + 1.0) * std::cos(2.0 * lat) +
         1500.0 * std::sin(7.0 * lon) * std::sin(5.0 * lat + 0.3);
}

// The pyramid `strata tile --to healpix` makes of the raster, with its pages' true ranges.
void tilePyramid(const std::filesystem::path& raster, const std::filesystem::path& pyramid) {
  const PluginRegistry plugins;
  tileRaster(plugins, {.input = raster, .output = pyramid, .target = "healpix", .nside = kNside});
}

void writeLongitudeLatitude(const std::filesystem::path& file) {
  constexpr int width = 4096, height = 2048;
  writeFloatRaster(file, width, height, {-180.0, -90.0, 180.0, 90.0}, [](int column, int row) {
    const double degree = std::numbers::pi / 180.0;
    return float(
        field((-180.0 + (column + 0.5) * 360.0 / width) * degree, (90.0 - (row + 0.5) * 180.0 / height) * degree));
  });
}

std::string pipeline(const std::string& geometry, const std::filesystem::path& heights) {
  return "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
         "  colours: {type: source.gdal, path: " +
         (heights.parent_path() / "checkerboard.tif").string() +
         "}\n"
         "  relief: {type: source.gdal, kind: height, path: " +
         heights.string() +
         ", scale: 20}\n"
         "  terrain: {type: " +
         geometry + (geometry == "geometry.pgm" ? ", pixel_error: 0" : "") +
         (geometry == "geometry.icosahedral" ? ", pixel_error: 0.05" : "") +
         ", height: relief, lowest: -120000, highest: 120000}\n"
         "  frame: {type: output.image, geometry: terrain, surface: [colours]}\n";
}

struct Comparison {
  ImageAgreement agreement;  // the pyramid's image against the raster's, away from both outlines
  int emptied = 0;           // pixels covered in the raster's image, and all round them, but empty in the pyramid's
  int outlineMoved = 0;      // pixels covered in one image only: the planet's and the mountains' outline moved
};

Comparison compare(const Image& pyramid, const Image& raster) {
  Comparison comparison{.agreement = agreementAwayFromSilhouettes(pyramid, raster)};
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      comparison.outlineMoved += covered(pyramid, x, y) != covered(raster, x, y);
      comparison.emptied += coveredAround(raster, x, y) && !covered(pyramid, x, y);
    }
  return comparison;
}

class HealpixPyramidHeights : public ::testing::TestWithParam<std::string> {};

TEST_P(HealpixPyramidHeights, GiveThePlanetTheLongitudeLatitudeRasterGives) {
  TemporaryDirectory directory;
  writeLongitudeLatitude(directory.path() / "raster.tif");
  tilePyramid(directory.path() / "raster.tif", directory.path() / "pyramid.tif");
  writeCheckerboard(directory.path() / "checkerboard.tif");
  auto engine = makeEngine();
  const double corner = std::asin(2.0 / 3.0) * 180.0 / std::numbers::pi;
  for (const Camera& camera :
       {Camera{.lon = 30, .lat = 25, .altitude = 8.0e6, .tilt = 0, .fov = 45},
        Camera{.lon = 0, .lat = corner, .altitude = 3.0e5, .heading = 40, .tilt = 50, .fov = 45},
        Camera{.lon = 20, .lat = 90, .altitude = 3.0e5, .heading = 0, .tilt = 30, .fov = 45},
        Camera{.lon = 0, .lat = corner, .altitude = 2.0e4, .heading = 130, .tilt = 60, .fov = 45}}) {
    engine->load(directory.write("pyramid.yaml", pipeline(GetParam(), directory.path() / "pyramid.tif")));
    // pgm's third frame has its primary sphere from the least visible height; the others need one frame.
    const int frames = GetParam() == "geometry.pgm" ? 3 : 1;
    const Image pyramid = renderFrames(*engine, camera, kWidth, kHeight, frames);
    const int pyramidNodes = engine->geometryStatistics().patches;
    engine->load(directory.write("raster.yaml", pipeline(GetParam(), directory.path() / "raster.tif")));
    const Image raster = renderFrames(*engine, camera, kWidth, kHeight, frames);
    const int rasterNodes = engine->geometryStatistics().patches;
    const Comparison comparison = compare(pyramid, raster);
    std::printf(
        "%s at %.0f, %.1f, %8.0f m up: %d pixels compared, mean difference %.2f levels, %.2f%% differ by "
        "more than %d, %d emptied, outline moved at %d; %d nodes or patches, %d from the raster\n",
        GetParam().c_str(), camera.lon, camera.lat, camera.altitude, comparison.agreement.compared,
        comparison.agreement.meanDifference, 100.0 * comparison.agreement.largeShare, kLargeDifference,
        comparison.emptied, comparison.outlineMoved, pyramidNodes, rasterNodes);
    EXPECT_GT(comparison.agreement.compared, kWidth * kHeight / 10);
    EXPECT_LT(comparison.agreement.meanDifference, kMeanTolerance);
    EXPECT_LT(comparison.agreement.largeShare, kLargeTolerance);
    EXPECT_EQ(comparison.emptied, 0);
    EXPECT_LE(comparison.outlineMoved, kOutlineTolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(Generators, HealpixPyramidHeights,
                         ::testing::Values("geometry.icosahedral", "geometry.pgm", "geometry.healpix",
                                           "geometry.clipmap"),
                         [](const ::testing::TestParamInfo<std::string>& type) {
                           return type.param.substr(type.param.find('.') + 1);
                         });

}  // namespace
}  // namespace strata::test
