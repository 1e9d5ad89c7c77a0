// Geometry generators trust the heights the terrain keeps within (geometry.icosahedral culls by them,
// geometry.pgm builds its reference spheres from them). Unset, they are the height layer's own
// (source.procedural's analytic bound, source.gdal's exact statistics or a raster small enough to count),
// widened to the sphere's 0; `lowest` and `highest` override them but may not leave out heights the layer
// knows it has; and a layer that does not know its heights needs both. Each is checked at load, by each
// generator, with the fix named.
#include <gtest/gtest.h>

#include <string>

#include <strata/error.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

std::string pipelineWith(const std::string& heights, const std::string& globe) {
  return "strata: 1\nnodes:\n  heights: " + heights + "\n  globe: " + globe +
         "\n  frame: {type: output.image, geometry: globe}\n";
}

// The message of the error loading `pipeline` throws, or "" when it loads.
std::string loadError(const std::string& pipeline) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  try {
    engine->load(directory.write("p.yaml", pipeline));
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

class HeightRange : public ::testing::TestWithParam<std::string> {};

TEST_P(HeightRange, AnExaggeratedProceduralReliefNeedsNoRange) {
  const std::string relief = "{type: source.procedural, kind: height, scale: 20}";
  EXPECT_EQ(loadError(pipelineWith(relief, "{type: " + GetParam() + ", height: heights}")), "");
  EXPECT_EQ(loadError(pipelineWith(relief, "{type: " + GetParam() + ", height: heights, lowest: -250000}")), "");
}

TEST_P(HeightRange, AGivenRangeMustHoldTheLayersHeights) {
  const std::string error = loadError(pipelineWith("{type: source.procedural, kind: height, scale: 20}",
                                                   "{type: " + GetParam() + ", height: heights, highest: 12000}"));
  EXPECT_NE(error.find("reaches from -240000 to 240000 m"), std::string::npos) << error;
  EXPECT_NE(error.find("set lowest: -240000 and highest: 240000"), std::string::npos) << error;
  EXPECT_NE(error.find("or leave both out"), std::string::npos) << error;
  EXPECT_NE(error.find("'globe'"), std::string::npos) << error;
}

TEST_P(HeightRange, AGdalRasterIsCountedWhenSmall) {
  TemporaryDirectory directory;
  writeFloatRaster(directory.path() / "tall.tif", 64, 32, {-180, -90, 180, 90},
                   [](int column, int) { return float(column * 500); });  // up to 31500 m
  const std::string tall = "{type: source.gdal, kind: height, path: " + (directory.path() / "tall.tif").string() + "}";
  EXPECT_EQ(loadError(pipelineWith(tall, "{type: " + GetParam() + ", height: heights}")), "");
  const std::string error =
      loadError(pipelineWith(tall, "{type: " + GetParam() + ", height: heights, highest: 30000}"));
  EXPECT_NE(error.find("reaches from 0 to 31500 m"), std::string::npos) << error;
}

// 8192 x 4096 texels, past what is counted at load (source-gdal/value_range.cpp), with no statistics: a
// sparse file, no block written, so the test writes kilobytes.
TEST_P(HeightRange, ALayerThatDoesNotKnowItsHeightsNeedsBoth) {
  TemporaryDirectory directory;
  const auto file = directory.path() / "large.tif";
  writeRasterFile(file, {.crs = "EPSG:4326",
                         .geotransform = {-180, 360.0 / 8192, 0, 90, 0, -180.0 / 4096},
                         .width = 8192,
                         .height = 4096,
                         .nodata = -32768.0,
                         .creationOptions = {"SPARSE_OK=TRUE", "TILED=YES"},
                         .values = false});
  const std::string large = "{type: source.gdal, kind: height, path: " + file.string() + "}";
  const std::string error = loadError(pipelineWith(large, "{type: " + GetParam() + ", height: heights, lowest: -100}"));
  EXPECT_NE(error.find("does not know the least and greatest heights"), std::string::npos) << error;
  EXPECT_NE(error.find("gdalinfo -stats"), std::string::npos) << error;
  EXPECT_NE(error.find("strata tile"), std::string::npos) << error;
  EXPECT_NE(error.find("'globe'"), std::string::npos) << error;
  EXPECT_EQ(loadError(pipelineWith(large, "{type: " + GetParam() + ", height: heights, lowest: -100, highest: 9000}")),
            "");
}

TEST_P(HeightRange, LowestAboveHighestIsRefused) {
  const std::string error = loadError(pipelineWith(
      "{type: source.procedural, kind: height}", "{type: " + GetParam() + ", height: heights, lowest: 5, highest: 1}"));
  EXPECT_NE(error.find("lowest (5 m) lies above highest (1 m)"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(Generators, HeightRange,
                         ::testing::Values("geometry.icosahedral", "geometry.pgm", "geometry.healpix",
                                           "geometry.clipmap"),
                         [](const ::testing::TestParamInfo<std::string>& type) {
                           return type.param.substr(type.param.find('.') + 1);
                         });

}  // namespace
}  // namespace strata::test
