// End-to-end tests of `strata tile`: rasters in and out through GDAL, checked for the pyramid's layout
// (512x512 tiles, overviews), the CRS chosen, values kept bit for bit, and errors that say what to do.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<GDALDataset> openRaster(const fs::path& file) {
  return std::unique_ptr<GDALDataset>(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

std::string projName(GDALDataset& dataset) {
  char* proj = nullptr;
  dataset.GetSpatialRef()->exportToProj4(&proj);
  std::string text = proj ? proj : "";
  CPLFree(proj);
  return text.substr(0, text.find(' '));
}

const RasterFileSpec kLongLat{"+proj=longlat +R=3396190", {-30.0, 0.1, 0.0, 15.0, 0.0, -0.1}, 1200, 600};

class TileCommand : public StrataCommandTest {};

TEST_F(TileCommand, WritesACloudOptimizedPyramidAndKeepsAProjectionStrataSamples) {
  writeRasterFile(file("in.tif"), kLongLat);
  const CommandResult result = run({"tile", file("in.tif").string(), file("out.tif").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "wrote")) << result.out;
  EXPECT_EQ(result.err, "") << "progress must be quiet when not on a terminal";
  auto out = openRaster(file("out.tif"));
  ASSERT_TRUE(out);
  EXPECT_STREQ(out->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE"), "COG");
  int blockWidth = 0, blockHeight = 0;
  out->GetRasterBand(1)->GetBlockSize(&blockWidth, &blockHeight);
  EXPECT_EQ(blockWidth, 512);
  EXPECT_EQ(blockHeight, 512);
  EXPECT_GE(out->GetRasterBand(1)->GetOverviewCount(), 1) << "1200x600 needs an overview to reach one tile";
  EXPECT_EQ(projName(*out), "+proj=longlat");
  ASSERT_EQ(out->GetRasterXSize(), 1200);
  int hasNodata = 0;
  EXPECT_EQ(out->GetRasterBand(1)->GetNoDataValue(&hasNodata), 255.0);
  EXPECT_TRUE(hasNodata);
  for (auto [x, y] : {std::array{0, 0}, {1199, 599}, {517, 311}}) {
    double value = -1.0;
    ASSERT_EQ(out->GetRasterBand(1)->RasterIO(GF_Read, x, y, 1, 1, &value, 1, 1, GDT_Float64, 0, 0), CE_None);
    EXPECT_EQ(value, rasterFileValue(x, y, 1)) << "lossless at " << x << "," << y;
  }
}

TEST_F(TileCommand, ReprojectsAnUnsupportedCrsIntoTheBestSuitedProjection) {
  // Web Mercator is not sampled directly; a mid-latitude raster goes to longitude/latitude...
  writeRasterFile(file("mercator.tif"), {"EPSG:3857", {-2e6, 5000.0, 0.0, 2e6, 0.0, -5000.0}, 400, 400, 3, GDT_Byte});
  CommandResult result = run({"tile", file("mercator.tif").string(), file("mercator-tiled.tif").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "reprojected to +proj=longlat")) << result.out;
  // ...and a Lambert azimuthal cap around the north pole to polar stereographic.
  writeRasterFile(file("cap.tif"), {"+proj=laea +lat_0=90 +lon_0=0 +R=3396190", {-1e6, 5000.0, 0.0, 1e6, 0.0, -5000.0}, 400,
                                400});
  result = run({"tile", file("cap.tif").string(), file("cap-tiled.tif").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto out = openRaster(file("cap-tiled.tif"));
  ASSERT_TRUE(out);
  EXPECT_EQ(projName(*out), "+proj=stere");
}

TEST_F(TileCommand, ReprojectsIntoTheProjectionNamed) {
  writeRasterFile(file("in.tif"), {"+proj=longlat +R=3396190", {-180.0, 0.5, 0.0, -50.0, 0.0, -0.5}, 720, 80});
  const CommandResult result =
      run({"tile", file("in.tif").string(), file("south.tif").string(), "--to", "polar-south"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto out = openRaster(file("south.tif"));
  ASSERT_TRUE(out);
  char* proj = nullptr;
  out->GetSpatialRef()->exportToProj4(&proj);
  EXPECT_TRUE(contains(proj, "+proj=stere +lat_0=-90")) << proj;
  CPLFree(proj);
}

TEST_F(TileCommand, RefusesToReplaceAnExistingOutputUnlessAsked) {
  writeRasterFile(file("in.tif"), kLongLat);
  const fs::path output = write("precious.tif", "a user's file");
  CommandResult result = run({"tile", file("in.tif").string(), output.string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "--overwrite")) << result.err;
  EXPECT_EQ(readText(output), "a user's file");
  result = run({"tile", file("in.tif").string(), output.string(), "--overwrite"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
}

TEST_F(TileCommand, BadInputsSayWhatIsWrongAndWhatToDo) {
  const fs::path text = write("notes.tif", "not a raster");
  CommandResult result = run({"tile", text.string(), file("a.tif").string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "GDAL cannot open")) << result.err;

  writeRasterFile(file("five.tif"), {kLongLat.crs, kLongLat.geotransform, 64, 32, 5, GDT_Byte});
  result = run({"tile", file("five.tif").string(), file("b.tif").string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "5 bands") && contains(result.err, "gdal_translate -b")) << result.err;

  writeRasterFile(file("in.tif"), kLongLat);
  result = run({"tile", file("in.tif").string(), file("c.tif").string(), "--to", "polar-sooth"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "polar-south")) << "the names are listed: " << result.err;
  EXPECT_FALSE(fs::exists(file("c.tif")));
}

}  // namespace
}  // namespace strata::test
