// Geometry generators trust the heights `lowest` and `highest` say the terrain keeps within
// (geometry.icosahedral culls by them, geometry.pgm builds its reference spheres from them); a height
// layer that knows its own heights (source.procedural always, source.gdal from exact statistics or a
// raster small enough to count) and reaches beyond them is refused at load, naming the fix, by each.
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

TEST_P(HeightRange, AnExaggeratedProceduralReliefNeedsTheRangeRaised) {
  const std::string error = loadError(pipelineWith("{type: source.procedural, kind: height, scale: 20}",
                                                   "{type: " + GetParam() + ", height: heights}"));
  EXPECT_NE(error.find("reaches from -240000 to 240000 m"), std::string::npos) << error;
  EXPECT_NE(error.find("set lowest: -240000 and highest: 240000"), std::string::npos) << error;
  EXPECT_NE(error.find("'globe'"), std::string::npos) << error;
}

TEST_P(HeightRange, AGdalRasterIsCountedWhenSmall) {
  TemporaryDirectory directory;
  writeFloatRaster(directory.path() / "tall.tif", 64, 32, {-180, -90, 180, 90},
                   [](int column, int) { return float(column * 500); });  // up to 31500 m
  const std::string tall = "{type: source.gdal, kind: height, path: " + (directory.path() / "tall.tif").string() + "}";
  const std::string error = loadError(pipelineWith(tall, "{type: " + GetParam() + ", height: heights}"));
  EXPECT_NE(error.find("reaches from 0 to 31500 m"), std::string::npos) << error;
  EXPECT_EQ(loadError(pipelineWith(tall, "{type: " + GetParam() + ", height: heights, highest: 31500}")), "");
}

TEST_P(HeightRange, LowestAboveHighestIsRefused) {
  const std::string error = loadError(pipelineWith("{type: source.procedural, kind: height}",
                                                   "{type: " + GetParam() + ", height: heights, lowest: 5, highest: 1}"));
  EXPECT_NE(error.find("lowest (5 m) lies above highest (1 m)"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(Generators, HeightRange, ::testing::Values("geometry.icosahedral", "geometry.pgm", "geometry.healpix"),
                         [](const ::testing::TestParamInfo<std::string>& type) {
                           return type.param.substr(type.param.find('.') + 1);
                         });

}  // namespace
}  // namespace strata::test
