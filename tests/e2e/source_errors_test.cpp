// End-to-end tests of what `strata render` says about rasters it cannot use. A CRS that is none of the
// registered projections and nodata values no sample can hold end in exit code 1 with the file and a fix.
// Truncated and corrupt files are read page by page, so they render: each page that cannot be read is
// reported once, with the file and a fix, and the coarser level stands in for it (or the layer is masked
// there when there is none), and only the tiles that cannot be read are left out of the heights culling
// trusts. Never a crash or a silent picture. A vector file is read as a mask of its
// polygons; one that has none, no layer of the name given, or no CRS, or one not asked for as a mask, is an
// error naming the file and what to do; so is a raster too large to page.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

const std::array<double, 6> kNearTheEquator{-30.0, 0.1, 0.0, 15.0, 0.0, -0.1};
// Heights in deflated tiles, whose damage a reader sees tile by tile; 255: no data.
const RasterFileSpec kDeflatedTiles{"+proj=longlat +R=3396190",       kNearTheEquator, 600, 300, 1, GDT_Float32, 255.0,
                                    {"TILED=YES", "COMPRESS=DEFLATE"}};

class SourceErrors : public StrataCommandTest {
 protected:
  // Lays a grey raster over itself where the vector file `vector` (`cut`, with `more` said of it) allows.
  CommandResult renderMask(const fs::path& vector, const std::string& more) const {
    writeRasterFile(file("grey.tif"), {"+proj=longlat +R=3396190", kNearTheEquator, 60, 30, 1, GDT_Byte});
    return renderTiny(write("p.yaml",
                            "strata: 1\nnodes:\n"
                            "  base: {type: source.gdal, path: " +
                                file("grey.tif").string() +
                                "}\n"
                                "  over: {type: source.gdal, path: " +
                                file("grey.tif").string() +
                                "}\n"
                                "  cut: {type: source.gdal, path: " +
                                vector.string() + more +
                                "}\n"
                                "  laid: {type: composite.overlay_mask, base: base, overlay: over, mask: cut}\n"
                                "  globe: {type: geometry.icosahedral}\n"
                                "  frame: {type: output.image, geometry: globe, surface: [laid]}\n"));
  }

  // Renders the source `source` (its path and what follows it) as output.image's input `port`.
  CommandResult renderLayer(const std::string& source, const std::string& port) const {
    return renderTiny(write("layer.yaml", "strata: 1\nnodes:\n  data: {type: source.gdal, path: " + source +
                                              "}\n  globe: {type: geometry.icosahedral}\n"
                                              "  frame: {type: output.image, geometry: globe, " +
                                              port + ": [data]}\n"));
  }

  CommandResult renderRaster(const fs::path& raster, const std::string& kind = "height") const {
    return renderTiny(write("p.yaml",
                            "strata: 1\nnodes:\n"
                            "  data: {type: source.gdal, path: " +
                                raster.string() + ", kind: " + kind +
                                "}\n"
                                "  globe: {type: geometry.icosahedral, height: data}\n"
                                "  frame: {type: output.image, geometry: globe}\n"));
  }
};

// Overwrites `count` bytes of `file` from `offset` with a pattern no codec decodes.
void damage(const fs::path& file, std::streamoff offset, std::size_t count) {
  std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
  stream.seekp(offset);
  const std::string garbage(count, '\xA5');
  stream.write(garbage.data(), static_cast<std::streamsize>(garbage.size()));
}

TEST_F(SourceErrors, AnUnknownCrsNamesTheFileAndSaysHowToTileIt) {
  writeRasterFile(file("mercator.tif"), {"EPSG:3857", {-2e6, 5000.0, 0.0, 2e6, 0.0, -5000.0}, 200, 200});
  const CommandResult result = renderRaster(file("mercator.tif"));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "+proj=merc")) << result.err;
  EXPECT_TRUE(contains(result.err, "p.yaml")) << "the pipeline line of the source: " << result.err;
  EXPECT_TRUE(contains(result.err, "strata tile")) << result.err;
}

// The warnings of a render, one per line that starts with "strata: warning: cannot read".
std::vector<std::string> pageWarnings(const std::string& err) {
  std::vector<std::string> warnings;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("strata: warning: cannot read")) warnings.push_back(line);
  return warnings;
}

// Each unreadable page is reported once, naming the file; the fix follows the first report of the file.
void expectEachPageReportedOnce(const CommandResult& result, const std::string& name) {
  EXPECT_EQ(result.exitCode, 0) << result.err;
  std::vector<std::string> warnings = pageWarnings(result.err);
  ASSERT_FALSE(warnings.empty()) << result.err;
  for (const std::string& warning : warnings) EXPECT_TRUE(contains(warning, name)) << warning;
  const std::string fix = "fix: check that the file is complete and readable: gdalinfo -checksum";
  const std::size_t first = result.err.find(fix);
  EXPECT_NE(first, std::string::npos) << result.err;
  EXPECT_EQ(result.err.find(fix, first + 1), std::string::npos) << "the fix given twice:\n" << result.err;
  std::ranges::sort(warnings);
  EXPECT_EQ(std::ranges::adjacent_find(warnings), warnings.end()) << "a page reported twice:\n" << result.err;
}

TEST_F(SourceErrors, ATruncatedRasterRendersWithEachUnreadablePageReportedOnce) {
  writeRasterFile(file("cut.tif"), {"+proj=longlat +R=3396190", kNearTheEquator, 600, 300});
  fs::resize_file(file("cut.tif"), fs::file_size(file("cut.tif")) / 2);
  expectEachPageReportedOnce(renderRaster(file("cut.tif")), "cut.tif");
}

TEST_F(SourceErrors, ACorruptCompressedTileRendersWithEachUnreadablePageReportedOnce) {
  writeRasterFile(file("bad.tif"), kDeflatedTiles);
  damage(file("bad.tif"), static_cast<std::streamoff>(fs::file_size(file("bad.tif")) / 2), 4096);
  expectEachPageReportedOnce(renderRaster(file("bad.tif")), "bad.tif");
}

// A height raster of which one tile cannot be read is still bounded by every other texel: a band of rows
// that cannot be read whole is counted again tile by tile, so a peak in the damaged tile's row of tiles
// counts, and the height range a pipeline gives must hold it.
TEST_F(SourceErrors, ACorruptTileLeavesOnlyItselfOutOfTheHeightsCounted) {
  writeRasterFile(file("bad.tif"), kDeflatedTiles);
  std::string offset, size;
  {
    std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file("bad.tif").c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE));
    ASSERT_TRUE(dataset);
    float peak = 5000.0f;  // in tile (2, 0), beside the tile (0, 0) damaged below
    ASSERT_EQ(dataset->GetRasterBand(1)->RasterIO(GF_Write, 550, 10, 1, 1, &peak, 1, 1, GDT_Float32, 0, 0), CE_None);
  }
  {
    std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file("bad.tif").c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    offset = dataset->GetRasterBand(1)->GetMetadataItem("BLOCK_OFFSET_0_0", "TIFF");
    size = dataset->GetRasterBand(1)->GetMetadataItem("BLOCK_SIZE_0_0", "TIFF");
  }
  damage(file("bad.tif"), std::stoll(offset), std::stoul(size));
  const CommandResult result =
      renderTiny(write("p.yaml",
                       "strata: 1\nnodes:\n"
                       "  data: {type: source.gdal, path: " +
                           file("bad.tif").string() +
                           ", kind: height}\n"
                           "  globe: {type: geometry.icosahedral, height: data, lowest: 0, highest: 300}\n"
                           "  frame: {type: output.image, geometry: globe}\n"));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "to 5000 m") && contains(result.err, "highest: 5000")) << result.err;
}

TEST_F(SourceErrors, NodataNoSampleCanHoldIsRefusedWithTheValueAndAFix) {
  writeRasterFile(file("bytes.tif"), {"+proj=longlat +R=3396190", kNearTheEquator, 60, 30, 1, GDT_Byte, -9999.0});
  const CommandResult result = renderRaster(file("bytes.tif"));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "nodata -9999")) << result.err;
  EXPECT_TRUE(contains(result.err, "gdal_edit.py")) << result.err;
}

// A GeoJSON FeatureCollection of one feature of `geometry`.
std::string geojson(const std::string& geometry) {
  return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry": )" + geometry +
         "}]}";
}

const std::string kTriangle = R"({"type": "Polygon", "coordinates": [[[-20, 0], [-10, 0], [-10, 10], [-20, 0]]]})";

void expectRefused(const CommandResult& result, const std::vector<std::string>& parts) {
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "p.yaml")) << "the pipeline line of the source: " << result.err;
  for (const std::string& part : parts) EXPECT_TRUE(contains(result.err, part)) << part << " in: " << result.err;
}

TEST_F(SourceErrors, AVectorFileWithoutPolygonsSaysItBoundsNoArea) {
  const fs::path lines = write("track.geojson", geojson(R"({"type": "LineString", "coordinates": [[0, 0], [10, 5]]})"));
  expectRefused(renderMask(lines, ", kind: mask"), {"track.geojson", "holds no polygons", "ogrinfo"});
}

TEST_F(SourceErrors, AVectorLayerThatDoesNotExistIsNamedWithTheLayersThereAre) {
  const fs::path triangle = write("triangle.geojson", geojson(kTriangle));
  expectRefused(renderMask(triangle, ", kind: mask, vector_layer: craters"),
                {"triangle.geojson", "no layer 'craters'", "it has triangle", "vector_layer"});
}

// A CSV of WKT polygons: OGR reads its geometry, and no CRS, from the WKT column.
TEST_F(SourceErrors, AVectorFileWithoutACrsAsksForOne) {
  const fs::path csv = write("triangle.csv", "WKT,id\n\"POLYGON ((-20 0,-10 0,-10 10,-20 0))\",1\n");
  expectRefused(renderMask(csv, ", kind: mask"), {"triangle.csv", "has no CRS", "projection", "ogr2ogr -a_srs"});
}

TEST_F(SourceErrors, AVectorFileNotReadAsAMaskAsksForOne) {
  const fs::path triangle = write("triangle.geojson", geojson(kTriangle));
  expectRefused(renderMask(triangle, ""), {"triangle.geojson", "is a vector file", "kind: mask"});
}

// Absurd sizes in a few hundred bytes of TIFF header, found by fuzzing (tests/fuzz/regressions): refused at
// load rather than read for minutes or into a gigabyte.
fs::path fuzzRegression(const std::string& name) {
  return fs::path(STRATA_SOURCE_DIR) / "tests/fuzz/regressions/raster_page" / name;
}

// xplanet's Earth (an RGB JPEG) given as heights: read from its first band without a word before; now refused
// with its bands named, and read as asked with `band`.
TEST_F(SourceErrors, AMultiBandRasterAsAOneChannelKindAsksForItsBand) {
  const std::string earth = "/usr/share/xplanet/images/earth.jpg";
  const CommandResult refused = renderRaster(earth);
  EXPECT_EQ(refused.exitCode, 1) << refused.err;
  EXPECT_TRUE(contains(refused.err, "'" + earth + "' has 3 bands (red, green, blue); a height layer reads one"))
      << refused.err;
  EXPECT_TRUE(contains(refused.err, "p.yaml:3:")) << "at the source's kind: " << refused.err;
  EXPECT_TRUE(contains(refused.err, "band: 1")) << refused.err;
  EXPECT_EQ(renderRaster(earth, "height, band: 2").exitCode, 0);
  const CommandResult beyond = renderRaster(earth, "height, band: 4");
  EXPECT_EQ(beyond.exitCode, 1);
  EXPECT_TRUE(contains(beyond.err, "no band 4")) << beyond.err;
  const CommandResult colour = renderLayer(earth + ", kind: color, band: 2", "surface");
  EXPECT_EQ(colour.exitCode, 1);
  EXPECT_TRUE(contains(colour.err, "a color layer reads red, green and blue")) << colour.err;
  writeRasterFile(file("grey.tif"), {"EPSG:4326", kNearTheEquator, 60, 30, 1, GDT_Byte});
  const CommandResult normal = renderLayer(file("grey.tif").string() + ", kind: normal", "normal");
  EXPECT_EQ(normal.exitCode, 1);
  EXPECT_TRUE(contains(normal.err, "a normal layer reads three: east, north, up")) << normal.err;
  const CommandResult objectSouth =
      renderLayer(earth + ", kind: normal, normal_space: object, normal_green: south", "normal");
  EXPECT_EQ(objectSouth.exitCode, 1);
  EXPECT_TRUE(contains(objectSouth.err, "normal_green: south is a tangent-space map's convention")) << objectSouth.err;
}

TEST_F(SourceErrors, ARasterWhoseCoarsestPageWouldAverageBillionsOfTexelsIsRefused) {
  expectRefused(renderRaster(fuzzRegression("slow-100000-square-without-overviews.tif")),
                {"100000x100000", "more than 2^30 texels", "strata tile", "gdaladdo"});
}

TEST_F(SourceErrors, ARasterStoredInGiantBlocksIsRefused) {
  expectRefused(renderRaster(fuzzRegression("oom-interleaved-giant-block.tif")),
                {"32x32784", "blocks of 1268 MiB", "strata tile", "TILED=YES"});
}

}  // namespace
}  // namespace strata::test
