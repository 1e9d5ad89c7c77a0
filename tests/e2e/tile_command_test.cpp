// End-to-end tests of `strata tile`: rasters in and out through GDAL, checked for the pyramid's layout
// (512x512 tiles, overviews), the CRS chosen, values kept bit for bit, the HEALPix pyramid's faces, and
// errors that say what to do.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <strata/crs.hpp>
#include <strata/plugin/block_ranges.hpp>
#include <strata/plugin/healpix.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/plugin_registry.hpp>

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

// Every longitude south of 50 S.
const RasterFileSpec kSouthernRing{"+proj=longlat +R=3396190", {-180.0, 0.5, 0.0, -50.0, 0.0, -0.5}, 720, 80};

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
  writeRasterFile(file("cap.tif"),
                  {"+proj=laea +lat_0=90 +lon_0=0 +R=3396190", {-1e6, 5000.0, 0.0, 1e6, 0.0, -5000.0}, 400, 400});
  result = run({"tile", file("cap.tif").string(), file("cap-tiled.tif").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto out = openRaster(file("cap-tiled.tif"));
  ASSERT_TRUE(out);
  EXPECT_EQ(projName(*out), "+proj=stere");
}

TEST_F(TileCommand, ReprojectsIntoTheProjectionNamed) {
  writeRasterFile(file("in.tif"), kSouthernRing);
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

// Every texel of band 1 that holds data (its mask's and finite) lies within its block's stored range, and a
// block is said to hold gaps exactly where some texel holds none.
void expectBlocksHoldTheirTexels(GDALDataset& tiled) {
  const int width = tiled.GetRasterXSize(), height = tiled.GetRasterYSize();
  const std::optional<BlockRanges> ranges = BlockRanges::fromMetadata(
      width, height, [&](const std::string& name) { return tiled.GetMetadataItem(name.c_str()); });
  ASSERT_TRUE(ranges) << "the file carries its blocks' ranges";
  std::vector<double> values(std::size_t(width) * height);
  std::vector<GByte> mask(values.size());
  ASSERT_EQ(
      tiled.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width, height, values.data(), width, height, GDT_Float64, 0, 0),
      CE_None);
  ASSERT_EQ(tiled.GetRasterBand(1)->GetMaskBand()->RasterIO(GF_Read, 0, 0, width, height, mask.data(), width, height,
                                                            GDT_Byte, 0, 0),
            CE_None);
  const int side = ranges->blockTexels();
  std::vector<bool> gaps(std::size_t(ranges->columns()) * ranges->rows(), false);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const std::size_t i = std::size_t(row) * width + column;
      if (mask[i] == 0 || !std::isfinite(values[i])) {
        gaps[std::size_t(row / side) * ranges->columns() + column / side] = true;
        continue;
      }
      const BlockRanges::Block& block = ranges->at(column / side, row / side);
      ASSERT_TRUE(values[i] >= block.least && values[i] <= block.greatest) << "texel " << column << ", " << row;
    }
  for (int row = 0; row < ranges->rows(); ++row)
    for (int column = 0; column < ranges->columns(); ++column)
      EXPECT_EQ(ranges->holdsGaps(column, row), gaps[std::size_t(row) * ranges->columns() + column])
          << "block " << column << ", " << row;
}

// One-channel pyramids carry the value ranges of their blocks of level-0 texels (strata/plugin/block_ranges.hpp), which
// bound a patch's heights by its data in a raster of any size: those of the texels written, reprojected too.
TEST_F(TileCommand, OneChannelPyramidsCarryTheirBlocksRanges) {
  writeRasterFile(file("in.tif"), kLongLat);
  writeRasterFile(file("ring.tif"), kSouthernRing);
  ASSERT_EQ(run({"tile", file("in.tif").string(), file("out.tif").string()}).exitCode, 0);
  ASSERT_EQ(run({"tile", file("ring.tif").string(), file("south.tif").string(), "--to", "polar-south"}).exitCode, 0);
  for (const std::string name : {"out.tif", "south.tif"}) {
    SCOPED_TRACE(name);
    expectBlocksHoldTheirTexels(*openRaster(file(name)));
  }
  RasterFileSpec colour = kLongLat;
  colour.bands = 3;
  colour.type = GDT_Byte;
  writeRasterFile(file("colour.tif"), colour);
  ASSERT_EQ(run({"tile", file("colour.tif").string(), file("colour-out.tif").string()}).exitCode, 0);
  EXPECT_EQ(openRaster(file("colour-out.tif"))->GetMetadataItem("STRATA_BLOCK_RANGES"), nullptr)
      << "colours bound no heights";
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

constexpr double kDegree = std::numbers::pi / 180.0;  // radians

// A smooth field on Mars (metres) of longitude and latitude in radians.
double marsField(double lon, double lat) {
  return 1000.0 * std::sin(lat) + 500.0 * std::cos(lat) * std::cos(lon - 0.3);
}

// Bilinear interpolation of a grid of spacing h = 0.5 degrees errs by at most h^2 / 8 (max |f_lonlon| +
// max |f_latlat|) = (pi / 360)^2 / 8 (500 + 1118) m = 0.0154 m for marsField; Float32 values below 1500 m
// add at most 1e-4 m. (Up to the poles and across the antimeridian too: strata tile interpolates across them.)
constexpr double kBilinearTolerance = 0.0155;

// A Float32 longitude/latitude raster on Mars's sphere, `width` x `height` texels of half a degree from
// (west, north) in degrees, holding marsField at texel centres; no nodata.
void writeMarsField(const fs::path& file, double west, double north, int width, int height) {
  writeRasterFile(file,
                  {"+proj=longlat +R=3396190", {west, 0.5, 0.0, north, 0.0, -0.5}, width, height, 1, GDT_Float32, {}});
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE));
  ASSERT_TRUE(dataset);
  std::vector<float> values(std::size_t(width) * std::size_t(height));
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      values[std::size_t(row) * width + column] =
          float(marsField((west + 0.5 * (column + 0.5)) * kDegree, (north - 0.5 * (row + 0.5)) * kDegree));
  ASSERT_EQ(dataset->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, width, height, values.data(), width, height,
                                                GDT_Float32, 0, 0),
            CE_None);
}

// A texel of a HEALPix pyramid's strip: face, and column and row in the face.
struct StripTexel {
  int face, column, row;
};

// The NESTED pixel a texel holds (strata/plugin/healpix_pyramid.hpp): f nside^2 + the bits of the column (even
// positions) and of nside - 1 - row (odd positions) interleaved.
std::int64_t nestedPixelOf(std::int64_t nside, StripTexel texel) {
  const std::int64_t ix = texel.column, iy = nside - 1 - texel.row;
  std::int64_t bits = 0;
  for (int bit = 0; bit < 31; ++bit) bits |= ((ix >> bit) & 1) << (2 * bit) | ((iy >> bit) & 1) << (2 * bit + 1);
  return texel.face * nside * nside + bits;
}

// The texel holding NESTED pixel `pixel`: the inverse of nestedPixelOf.
StripTexel stripTexelOf(std::int64_t nside, std::int64_t pixel) {
  const std::int64_t bits = pixel % (nside * nside);
  std::int64_t ix = 0, iy = 0;
  for (int bit = 0; bit < 31; ++bit) {
    ix |= ((bits >> (2 * bit)) & 1) << bit;
    iy |= ((bits >> (2 * bit + 1)) & 1) << bit;
  }
  return {int(pixel / (nside * nside)), int(ix), int(nside - 1 - iy)};
}

// A band of a HEALPix pyramid read whole, with its mask (0 where the page cache reads coverage 0).
struct Strip {
  std::int64_t nside = 0;
  std::vector<float> values;
  std::vector<unsigned char> mask;
  float at(StripTexel t) const {
    return values[std::size_t(t.row) * std::size_t(12 * nside) + std::size_t(t.face * nside + t.column)];
  }
  bool covered(StripTexel t) const {
    return mask[std::size_t(t.row) * std::size_t(12 * nside) + std::size_t(t.face * nside + t.column)] != 0;
  }
};

Strip readStrip(GDALDataset& dataset, std::int64_t nside) {
  Strip strip{nside, std::vector<float>(std::size_t(12 * nside * nside)),
              std::vector<unsigned char>(std::size_t(12 * nside * nside))};
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  const int width = int(12 * nside), height = int(nside);
  EXPECT_EQ(band.RasterIO(GF_Read, 0, 0, width, height, strip.values.data(), width, height, GDT_Float32, 0, 0),
            CE_None);
  EXPECT_EQ(
      band.GetMaskBand()->RasterIO(GF_Read, 0, 0, width, height, strip.mask.data(), width, height, GDT_Byte, 0, 0),
      CE_None);
  return strip;
}

// Texels to check: `count` at random over the strip, and those of places next to both poles and along
// both sides of the antimeridian.
std::vector<StripTexel> texelsToCheck(std::int64_t nside, int count) {
  std::mt19937 random(20261123);
  std::uniform_int_distribution<std::int64_t> pixel(0, 12 * nside * nside - 1);
  std::vector<StripTexel> texels;
  for (int i = 0; i < count; ++i) texels.push_back(stripTexelOf(nside, pixel(random)));
  for (int face = 0; face < 4; ++face) {
    texels.push_back({face, int(nside) - 1, 0});      // the north pole is faces 0-3's northern corner
    texels.push_back({face + 8, 0, int(nside) - 1});  // the south pole faces 8-11's southern corner
  }
  for (double lat = -89.9; lat < 90.0; lat += 0.7)
    for (const double lon : {179.97, -179.97, 179.8, -179.8})
      texels.push_back(stripTexelOf(nside, healpix::nestedPixel(nside, glm::dvec2(lon, lat) * kDegree)));
  for (int column = 0; column < nside; column += 7)  // face 6's centres on the antimeridian itself
    texels.push_back({6, column, int(nside) - 1 - column});
  return texels;
}

TEST_F(TileCommand, WritesAHealpixPyramidOfTheTwelveFacesSideBySide) {
  writeMarsField(file("mars.tif"), -180.0, 90.0, 720, 360);
  const CommandResult result =
      run({"tile", file("mars.tif").string(), file("healpix.tif").string(), "--to", "healpix"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "HEALPix pyramid of nside 512 (NESTED)")) << result.out;
  EXPECT_EQ(result.err, "") << "nothing but the summary when not on a terminal";
  auto out = openRaster(file("healpix.tif"));
  ASSERT_TRUE(out);
  ASSERT_EQ(out->GetRasterXSize(), 6144) << "half-degree texels need the least nside, 512";
  ASSERT_EQ(out->GetRasterYSize(), 512);
  int blockWidth = 0, blockHeight = 0;
  out->GetRasterBand(1)->GetBlockSize(&blockWidth, &blockHeight);
  EXPECT_EQ(blockWidth, 512);
  EXPECT_EQ(blockHeight, 512);
  EXPECT_EQ(out->GetRasterBand(1)->GetRasterDataType(), GDT_Float32);
  EXPECT_STREQ(out->GetMetadataItem(healpix::kNsideItem), "512");
  EXPECT_STREQ(out->GetMetadataItem(healpix::kFigureItem), "+proj=healpix +R=3396190");
  EXPECT_STREQ(out->GetMetadataItem(healpix::kOrderingItem), "NESTED");
  EXPECT_EQ(out->GetSpatialRef(), nullptr);
  std::array<double, 6> geotransform{};
  ASSERT_EQ(out->GetGeoTransform(geotransform.data()), CE_None);
  EXPECT_EQ(geotransform, healpix::stripGeotransform(512));
  const Strip strip = readStrip(*out, 512);
  std::array<int, 12> checkedPerFace{};
  for (const StripTexel texel : texelsToCheck(512, 3000)) {
    const glm::dvec2 centre = healpix::nestedPixelCentre(512, nestedPixelOf(512, texel));
    ASSERT_TRUE(strip.covered(texel)) << "face " << texel.face << " column " << texel.column << " row " << texel.row;
    EXPECT_NEAR(strip.at(texel), marsField(centre.x, centre.y), kBilinearTolerance)
        << "face " << texel.face << " column " << texel.column << " row " << texel.row << " at longitude "
        << centre.x / kDegree << ", latitude " << centre.y / kDegree;
    ++checkedPerFace[texel.face];
  }
  for (int face = 0; face < 12; ++face) EXPECT_GT(checkedPerFace[face], 100) << "face " << face;
}

// One-channel pyramids carry their pages' true ranges (healpix::PageRanges): every node's holds the texels of
// the page it lies in, and knows where there is no data.
TEST_F(TileCommand, AHealpixPyramidOfHeightsCarriesItsPagesTrueRanges) {
  writeMarsField(file("mars.tif"), -180.0, 90.0, 720, 360);
  writeMarsField(file("region.tif"), -20.0, 30.0, 120, 80);
  for (const std::string name : {"mars", "region"})
    ASSERT_EQ(run({"tile", file(name + ".tif").string(), file(name + "-healpix.tif").string(), "--to", "healpix",
                   "--nside", "1024"})
                  .exitCode,
              0);
  auto tiled = openRaster(file("mars-healpix.tif"));
  const auto item = [&](GDALDataset& dataset) {
    return [&dataset](const std::string& name) { return dataset.GetMetadataItem(name.c_str()); };
  };
  const std::optional<healpix::PageRanges> ranges = healpix::PageRanges::fromMetadata(1024, item(*tiled));
  ASSERT_TRUE(ranges);
  const Strip strip = readStrip(*tiled, 1024);
  const auto [least, greatest] = std::ranges::minmax(strip.values);
  double widths = 0.0;
  for (int face = 0; face < 12; ++face)
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 2; ++ix) {
        const healpix::PageRanges::Range range = ranges->overNode(face, 1, ix, iy);  // one level-0 page
        EXPECT_FALSE(range.uncovered);
        for (int row = (1 - iy) * 512; row < (2 - iy) * 512; ++row)
          for (int column = ix * 512; column < (ix + 1) * 512; ++column) {
            const float value = strip.at({face, column, row});
            ASSERT_TRUE(value >= range.least && value <= range.greatest)
                << "face " << face << " node " << ix << ", " << iy;
          }
        widths += range.greatest - range.least;
      }
  EXPECT_LT(widths / 48.0, 0.8 * (greatest - least)) << "a node's range is its neighbourhood's, not the planet's";

  auto region = openRaster(file("region-healpix.tif"));
  const std::optional<healpix::PageRanges> regional = healpix::PageRanges::fromMetadata(1024, item(*region));
  ASSERT_TRUE(regional);
  const healpix::PageRanges::Range far = regional->overNode(10, 3, 2, 2);  // around longitude 225, latitude -42
  EXPECT_TRUE(far.uncovered);
  EXPECT_GT(far.least, far.greatest) << "no data at all there";
  EXPECT_TRUE(regional->overNode(4, 0, 0, 0).uncovered);  // the region lies in face 4 but does not fill it
}

TEST_F(TileCommand, AHealpixPyramidOfAGlobeFromLongitude0IsTheSameAsFromMinus180) {
  writeMarsField(file("west.tif"), -180.0, 90.0, 720, 360);
  writeMarsField(file("east.tif"), 0.0, 90.0, 720, 360);
  for (const std::string name : {"west", "east"}) {
    const CommandResult result =
        run({"tile", file(name + ".tif").string(), file(name + "-healpix.tif").string(), "--to", "healpix"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
  }
  auto west = openRaster(file("west-healpix.tif"));
  auto east = openRaster(file("east-healpix.tif"));
  ASSERT_TRUE(west && east);
  const Strip fromWest = readStrip(*west, 512), fromEast = readStrip(*east, 512);
  EXPECT_EQ(fromWest.mask, fromEast.mask);
  EXPECT_EQ(fromWest.values, fromEast.values) << "the same texels at the same places";
}

// A grid of texel centres (as EGM96's: the first column centred on -180, rows on the poles) starts half a
// texel west of the antimeridian: the pyramid is covered all round the globe all the same.
TEST_F(TileCommand, AHealpixPyramidOfAGridOfTexelCentresIsCoveredAcrossTheAntimeridian) {
  writeMarsField(file("centres.tif"), -180.25, 90.25, 720, 361);
  ASSERT_EQ(
      run({"tile", file("centres.tif").string(), file("centres-healpix.tif").string(), "--to", "healpix"}).exitCode, 0);
  auto tiled = openRaster(file("centres-healpix.tif"));
  const Strip strip = readStrip(*tiled, 512);
  for (const StripTexel texel : texelsToCheck(512, 3000)) {
    const glm::dvec2 centre = healpix::nestedPixelCentre(512, nestedPixelOf(512, texel));
    ASSERT_TRUE(strip.covered(texel)) << "longitude " << centre.x / kDegree << ", latitude " << centre.y / kDegree;
    EXPECT_NEAR(strip.at(texel), marsField(centre.x, centre.y), kBilinearTolerance);
  }
}

TEST_F(TileCommand, AHealpixPyramidMarksWhereTheInputHasNoData) {
  // 60 x 40 degrees of a Float32 field, without nodata: NaN marks the rest.
  writeMarsField(file("region.tif"), -20.0, 30.0, 120, 80);
  CommandResult result =
      run({"tile", file("region.tif").string(), file("region-healpix.tif").string(), "--to", "healpix"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto tiled = openRaster(file("region-healpix.tif"));
  ASSERT_TRUE(tiled);
  ASSERT_EQ(tiled->GetRasterXSize(), 6144);
  const Strip strip = readStrip(*tiled, 512);
  int inside = 0, outside = 0;
  for (const StripTexel texel : texelsToCheck(512, 20000)) {
    const glm::dvec2 c = healpix::nestedPixelCentre(512, nestedPixelOf(512, texel)) / kDegree;
    if (c.x > -20.0 && c.x < 40.0 && c.y > -10.0 && c.y < 30.0) {
      if (c.x < -19.75 || c.x > 39.75 || c.y < -9.75 || c.y > 29.75) continue;  // beyond the outer texel centres
      ++inside;
      ASSERT_TRUE(strip.covered(texel)) << "longitude " << c.x << ", latitude " << c.y;
      EXPECT_NEAR(strip.at(texel), marsField(c.x * kDegree, c.y * kDegree), kBilinearTolerance);
    } else {
      ++outside;
      ASSERT_FALSE(strip.covered(texel)) << "longitude " << c.x << ", latitude " << c.y;
      EXPECT_TRUE(std::isnan(strip.at(texel))) << "not a height of 0 but no data";
    }
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(outside, 10000);

  // Integers keep their type with its most negative value as nodata; colour gains an alpha band.
  const StripTexel covered = stripTexelOf(512, healpix::nestedPixel(512, glm::dvec2(10.0, 10.0) * kDegree));
  const StripTexel missing = stripTexelOf(512, healpix::nestedPixel(512, glm::dvec2(100.0, -60.0) * kDegree));
  writeRasterFile(file("int16.tif"),
                  {"+proj=longlat +R=3396190", {-20.0, 0.5, 0.0, 30.0, 0.0, -0.5}, 120, 80, 1, GDT_Int16, {}});
  writeRasterFile(file("rgb.tif"),
                  {"+proj=longlat +R=3396190", {-20.0, 0.5, 0.0, 30.0, 0.0, -0.5}, 120, 80, 3, GDT_Byte, {}});
  for (const std::string name : {"int16", "rgb"}) {
    result = run({"tile", file(name + ".tif").string(), file(name + "-healpix.tif").string(), "--to", "healpix"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    auto pyramid = openRaster(file(name + "-healpix.tif"));
    ASSERT_TRUE(pyramid);
    const Strip coverage = readStrip(*pyramid, 512);
    EXPECT_TRUE(coverage.covered(covered)) << name;
    EXPECT_FALSE(coverage.covered(missing)) << name;
  }
  auto int16 = openRaster(file("int16-healpix.tif"));
  int hasNodata = 0;
  EXPECT_EQ(int16->GetRasterBand(1)->GetNoDataValue(&hasNodata), -32768.0);
  EXPECT_EQ(int16->GetRasterBand(1)->GetRasterDataType(), GDT_Int16);
  auto rgb = openRaster(file("rgb-healpix.tif"));
  ASSERT_EQ(rgb->GetRasterCount(), 4);
  EXPECT_EQ(rgb->GetRasterBand(4)->GetColorInterpretation(), GCI_AlphaBand);
  EXPECT_EQ(rgb->GetRasterBand(1)->GetRasterDataType(), GDT_Byte);
}

TEST_F(TileCommand, AHealpixPyramidsNsideIsAPowerOfTwoFrom512) {
  writeMarsField(file("mars.tif"), -180.0, 90.0, 720, 360);
  for (const auto& [nside, says] : {std::pair{"1000", "not a power of two"}, {"256", "below 512"}}) {
    const CommandResult result =
        run({"tile", file("mars.tif").string(), file("refused.tif").string(), "--to", "healpix", "--nside", nside});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(contains(result.err, std::string("nside ") + nside + " is " + says) && contains(result.err, "1024"))
        << result.err;
    EXPECT_FALSE(fs::exists(file("refused.tif")));
  }
  CommandResult result = run({"tile", file("mars.tif").string(), file("plane.tif").string(), "--nside", "1024"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "--to healpix")) << "--nside is only for the pyramid: " << result.err;
  result = run({"tile", file("mars.tif").string(), file("fine.tif").string(), "--to", "healpix", "--nside", "1024"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto out = openRaster(file("fine.tif"));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->GetRasterXSize(), 12288);
  EXPECT_EQ(out->GetRasterYSize(), 1024);
  EXPECT_STREQ(out->GetMetadataItem(healpix::kNsideItem), "1024");
  EXPECT_FALSE(fs::exists(file("fine.tif.strip.tif"))) << "the temporary strip is removed";
}

// 2.2 cm texels (2e-7 degrees of WGS84's equator) near Gale crater's place, holding 1000 column + row: a
// field bilinear filtering keeps exactly, so that a texel of the pyramid must hold it at its pixel's centre
// within Float32's rounding of values up to 2e5 (0.008) and the warper's error in placing the pixel: PROJ's
// inverse HEALPix on an ellipsoid takes the authalic latitude back by a series good to 5e-9 degrees (0.56 mm
// at lat -4.6 by gdaltransform, 0.025 rows here; longitudes exact): 0.05.
constexpr double kFineStep = 2e-7;
constexpr int kFineWidth = 200, kFineHeight = 100;
constexpr double kFineWest = 137.4, kFineNorth = -4.6;

double fineField(double lonDegrees, double latDegrees) {
  const double column = (lonDegrees - kFineWest) / kFineStep - 0.5, row = (kFineNorth - latDegrees) / kFineStep - 0.5;
  return 1000.0 * column + row;
}

// The window's texels covered, checked against fineField where their centres lie inside the input by more
// than a texel; returns how many were checked.
int checkWindow(GDALDataset& out, const healpix::FaceWindow& window, std::int64_t nside) {
  const std::unique_ptr<Projection> strip =
      healpix::stripProjection(projectionOfCrs(PluginRegistry{}, out.GetMetadataItem(healpix::kFigureItem), {}));
  std::vector<float> values(std::size_t(window.width) * std::size_t(window.height));
  EXPECT_EQ(out.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, window.width, window.height, values.data(), window.width,
                                           window.height, GDT_Float32, 0, 0),
            CE_None);
  int checked = 0;
  for (int row = 0; row < window.height; row += 3)
    for (int column = 0; column < window.width; column += 3) {
      const glm::dvec2 xy(window.face + (double(window.column + column) + 0.5) / double(nside),
                          1.0 - (double(window.row + row) + 0.5) / double(nside));
      const glm::dvec2 lonlat = *strip->inverse(xy) / kDegree;
      const double inputColumn = (lonlat.x - kFineWest) / kFineStep, inputRow = (kFineNorth - lonlat.y) / kFineStep;
      if (inputColumn < 1.5 || inputRow < 1.5 || inputColumn > kFineWidth - 1.5 || inputRow > kFineHeight - 1.5)
        continue;
      const float value = values[std::size_t(row) * std::size_t(window.width) + std::size_t(column)];
      EXPECT_NEAR(value, fineField(lonlat.x, lonlat.y), 0.05) << "window texel " << column << ", " << row;
      ++checked;
    }
  return checked;
}

// Finer than 2^26 (about 10 cm texels on Earth) a pyramid holds the window of the one face its input covers
// (healpix::FaceWindow): 2.2 cm texels need nside 2^29, whose strip would be 12 x 2^29 texels across.
TEST_F(TileCommand, AHealpixPyramidFinerThanTheStripAllowsHoldsAWindowOfOneFace) {
  writeFloatRaster(file("fine.tif"), kFineWidth, kFineHeight,
                   {kFineWest, kFineNorth - kFineHeight * kFineStep, kFineWest + kFineWidth * kFineStep, kFineNorth},
                   [](int column, int row) { return float(1000 * column + row); });
  const CommandResult result = run({"tile", file("fine.tif").string(), file("window.tif").string(), "--to", "healpix"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "nside 536870912")) << "the least nside with texels below 2.2 cm: " << result.out;
  auto out = openRaster(file("window.tif"));
  ASSERT_TRUE(out);
  constexpr std::int64_t kNside = std::int64_t{1} << 29;
  ASSERT_NE(out->GetMetadataItem(healpix::kWindowItem), nullptr);
  const std::optional<healpix::FaceWindow> window = healpix::windowOf(
      out->GetMetadataItem(healpix::kWindowItem), kNside, out->GetRasterXSize(), out->GetRasterYSize());
  ASSERT_TRUE(window) << out->GetMetadataItem(healpix::kWindowItem);
  EXPECT_EQ(window->face, healpix::facePoint(glm::dvec2(kFineWest, kFineNorth) * kDegree).face);
  // The input is 4.4 x 2.2 m, turned by about 45 degrees in the face: at most (4.4 + 2.2) / sqrt 2 m a side.
  EXPECT_LT(window->width, 4.7 / 0.0121 * 1.03 + 8);
  EXPECT_LT(window->height, 4.7 / 0.0121 * 1.03 + 8);
  std::array<double, 6> geotransform{};
  ASSERT_EQ(out->GetGeoTransform(geotransform.data()), CE_None);
  EXPECT_EQ(geotransform, healpix::windowGeotransform(kNside, *window));
  EXPECT_GT(checkWindow(*out, *window, kNside), 1000);
}

TEST_F(TileCommand, AHealpixPyramidFinerThanTheStripAllowsMustLieOnOneFace) {
  // 45 degrees east on the equator, the corner where the equatorial faces 4 and 5 meet polar faces 0 and 8.
  writeFloatRaster(file("corner.tif"), 100, 100, {45.0 - 1e-5, -1e-5, 45.0 + 1e-5, 1e-5},
                   [](int, int) { return 1.0f; });
  const CommandResult result = run(
      {"tile", file("corner.tif").string(), file("refused.tif").string(), "--to", "healpix", "--nside", "134217728"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "reaches faces 0, 4, 5, 8") && contains(result.err, "--nside 67108864"))
      << result.err;
  EXPECT_FALSE(fs::exists(file("refused.tif")));
}

TEST_F(TileCommand, TheHealpixPlaneIsACrsLikeAnyOther) {
  writeRasterFile(file("in.tif"), {"EPSG:4326", {-180.0, 0.5, 0.0, 60.0, 0.0, -0.5}, 720, 240});
  const CommandResult result =
      run({"tile", file("in.tif").string(), file("plane.tif").string(), "--to", "+proj=healpix"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "reprojected to +proj=healpix")) << result.out;
  auto out = openRaster(file("plane.tif"));
  ASSERT_TRUE(out);
  EXPECT_EQ(projName(*out), "+proj=healpix");
  EXPECT_EQ(out->GetMetadataItem(healpix::kNsideItem), nullptr);
}

}  // namespace
}  // namespace strata::test
