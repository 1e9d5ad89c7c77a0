// End-to-end tests of rasters with bad values or bad structure (docs/robustness.md): each is a clear error
// at load naming the file and a fix, or drawn with the bad texels masked, never a crash, a hang or a
// picture of garbage. Damaged files of the formats read page by page (TIFF in source_errors_test.cpp, PNG
// and JPEG here) draw with each unreadable page reported.
#include <gtest/gtest.h>

#include <gdal.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <strata/plugin/block_ranges.hpp>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

const std::array<double, 4> kGlobe{-180.0, -90.0, 180.0, 90.0};
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Heights of 1000 m with `bad` on every other 8x8 block of a 64x32 global raster.
std::function<float(int, int)> blocksOf(float bad) {
  return [bad](int column, int row) { return (column / 8 + row / 8) % 2 ? bad : 1000.0f; };
}

// A raster GDAL describes in a few lines of VRT: a band of zeros with no file behind it (and `band`, its
// overviews for one; `metadata`, MDI elements of the dataset's).
std::string vrt(const std::string& size, const std::string& srs, const std::string& geotransform,
                const std::string& band = "", const std::string& metadata = "") {
  return "<VRTDataset " + size + ">" + (srs.empty() ? "" : "<SRS>" + srs + "</SRS>") +
         (geotransform.empty() ? "" : "<GeoTransform>" + geotransform + "</GeoTransform>") +
         (metadata.empty() ? "" : "<Metadata>" + metadata + "</Metadata>") +
         "<VRTRasterBand dataType=\"Float32\" band=\"1\">" + band + "</VRTRasterBand></VRTDataset>";
}

// A VRT band's overview: band 1 of `file`.
std::string overviewElement(const fs::path& file) {
  return "<Overview><SourceFilename>" + file.string() + "</SourceFilename><SourceBand>1</SourceBand></Overview>";
}

const std::string kGlobalGeotransform = "-180, 5.625, 0, 90, 0, -5.625";

class BadData : public StrataCommandTest {
 protected:
  CommandResult renderHeights(const fs::path& raster, const std::string& size = "32x18") const {
    const fs::path pipeline = write("p.yaml",
                                    "strata: 1\nnodes:\n"
                                    "  data: {type: source.gdal, path: " +
                                        raster.string() +
                                        ", kind: height}\n"
                                        "  globe: {type: geometry.icosahedral, height: data, highest: 2000}\n"
                                        "  frame: {type: output.image, geometry: globe}\n");
    return run({"render", pipeline.string(), "--size", size, "-o", file("x.png").string(), "--overwrite"});
  }

  CommandResult renderColour(const fs::path& raster, const std::string& size) const {
    const fs::path pipeline = write("p.yaml",
                                    "strata: 1\nnodes:\n"
                                    "  data: {type: source.gdal, path: " +
                                        raster.string() +
                                        "}\n"
                                        "  globe: {type: geometry.icosahedral}\n"
                                        "  frame: {type: output.image, geometry: globe, surface: [data]}\n");
    return run({"render", pipeline.string(), "--size", size, "-o", file("x.png").string(), "--overwrite"});
  }

  // `raster` draws exactly what `reference` draws, with nothing said about it.
  void expectDrawnAlike(const fs::path& raster, const fs::path& reference) const {
    const CommandResult result = renderHeights(raster, "96x54");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_FALSE(contains(result.err, "warning")) << result.err;
    const Image drawn = readImage(file("x.png"));
    const CommandResult referenceRun = renderHeights(reference, "96x54");
    ASSERT_EQ(referenceRun.exitCode, 0) << referenceRun.err;
    EXPECT_EQ(drawn.rgba, readImage(file("x.png")).rgba);
  }

  // Heights with `bad` in half the blocks must be masked exactly as those blocks declared nodata are.
  void expectMaskedAsNodata(float bad) const {
    writeFloatRaster(file("bad.tif"), 64, 32, kGlobe, blocksOf(bad));
    writeFloatRaster(file("nodata.tif"), 64, 32, kGlobe, blocksOf(-9999.0f), -9999.0);
    expectDrawnAlike(file("bad.tif"), file("nodata.tif"));
  }

  // Heights of 1e-38 m, or none at all, draw exactly what heights of 0 m draw: the bare sphere.
  void expectDrawnAsTheBareSphere(const fs::path& raster) const {
    writeFloatRaster(file("zero.tif"), 64, 32, kGlobe, [](int, int) { return 0.0f; });
    expectDrawnAlike(raster, file("zero.tif"));
  }

  void expectRefused(const CommandResult& result, const std::vector<std::string>& parts) const {
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_TRUE(contains(result.err, "p.yaml:3")) << "the pipeline line of the source: " << result.err;
    for (const std::string& part : parts) EXPECT_TRUE(contains(result.err, part)) << part << " in: " << result.err;
  }
};

TEST_F(BadData, NaNHeightsAreMaskedAsNodataIs) { expectMaskedAsNodata(kNaN); }

TEST_F(BadData, InfiniteHeightsAreMaskedAsNodataIsAndBoundNothing) { expectMaskedAsNodata(kInfinity); }

TEST_F(BadData, HugeHeightsAreRefusedAsAnUndeclaredFillValue) {
  writeFloatRaster(file("fill.tif"), 64, 32, kGlobe, blocksOf(-3.4e38f));
  expectRefused(renderHeights(file("fill.tif")), {"fill.tif", "-3.4e+38", "gdal_edit.py -a_nodata"});
}

TEST_F(BadData, TinyHeightsDrawAsTheBareSphere) {
  writeFloatRaster(file("tiny.tif"), 64, 32, kGlobe, [](int column, int) { return 1e-38f * float(column % 3); });
  expectDrawnAsTheBareSphere(file("tiny.tif"));
}

TEST_F(BadData, AllNodataDrawsTheBareSphere) {
  writeFloatRaster(
      file("none.tif"), 64, 32, kGlobe, [](int, int) { return -9999.0f; }, -9999.0);
  expectDrawnAsTheBareSphere(file("none.tif"));
}

TEST_F(BadData, AnEmptyFileIsRefusedAsEmpty) {
  expectRefused(renderHeights(write("empty.tif", "")), {"empty.tif' is empty (0 bytes)"});
}

TEST_F(BadData, ARasterOfNoTexelsIsRefused) {
  expectRefused(
      renderHeights(write("zero.vrt", vrt("rasterXSize=\"0\" rasterYSize=\"0\"", "EPSG:4326", kGlobalGeotransform))),
      {"zero.vrt", "gdalinfo"});
}

const std::string kAbsurdSize = "rasterXSize=\"2000000000\" rasterYSize=\"1000000000\"";
const std::string kAbsurdGeotransform = "-180, 1.8e-7, 0, 90, 0, -1.8e-7";

TEST_F(BadData, AbsurdDimensionsWithoutOverviewsAreRefusedWithTheirSize) {
  const CommandResult result = renderHeights(write("absurd.vrt", vrt(kAbsurdSize, "EPSG:4326", kAbsurdGeotransform)));
  expectRefused(result, {"absurd.vrt' (2000000000x1000000000)", "more than 2^30 texels", "gdaladdo"});
}

// With an overview a page across, the coarsest page is cheap to read, but the page index cannot hold the
// pyramid's 10^13 pages (was: std::bad_alloc).
TEST_F(BadData, AbsurdDimensionsWithOverviewsAreRefusedWithTheirPageCount) {
  writeFloatRaster(file("overview.tif"), 512, 256, kGlobe, [](int, int) { return 0.0f; });
  const CommandResult result = renderHeights(
      write("absurd.vrt", vrt(kAbsurdSize, "EPSG:4326", kAbsurdGeotransform, overviewElement(file("overview.tif")))));
  expectRefused(result, {"2000000000x1000000000", "more than the page index holds", "gdal_translate -outsize"});
}

// Block ranges `strata tile` stored (strata/plugin/block_ranges.hpp) in a raster too large to count (4100 x 4100
// zeros), saying `value` in every block, as a file rescaled after tiling keeps them.
std::string claimingBlocks(float value) {
  BlockRanges ranges(4100, 4100, BlockRanges::blockTexelsFor(4100, 4100));
  for (int row = 0; row < ranges.height(); ++row)
    for (int column = 0; column < ranges.width(); ++column) ranges.count(column, row, value);
  std::string items;
  for (const auto& [name, text] : ranges.metadataItems()) items += "<MDI key=\"" + name + "\">" + text + "</MDI>";
  return items;
}

// Ranges the file's coarsest overview contradicts are not trusted (culling by them would drop the terrain),
// and the user is told why and what to do; ranges it agrees with are taken without a word.
TEST_F(BadData, BlockRangesTheOverviewContradictsAreIgnoredWithAWarning) {
  writeFloatRaster(file("overview.tif"), 128, 128, kGlobe, [](int, int) { return 0.0f; });
  const std::string overview = overviewElement(file("overview.tif"));
  const std::string size = "rasterXSize=\"4100\" rasterYSize=\"4100\"";
  const std::string globe = "-180, 0.087804878048780488, 0, 90, 0, -0.043902439024390244";
  CommandResult result =
      renderHeights(write("stale.vrt", vrt(size, "EPSG:4326", globe, overview, claimingBlocks(1500.0f))));
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.err, "stale.vrt' carries block ranges that its coarsest overview contradicts") &&
              contains(result.err, "run `strata tile` on it again"))
      << result.err;
  result = renderHeights(write("agreeing.vrt", vrt(size, "EPSG:4326", globe, overview, claimingBlocks(0.0f))));
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_FALSE(contains(result.err, "warning")) << result.err;
}

// A geotransform that places a raster nowhere (was: an empty planet, exit 0): NaN or infinite terms, texels
// of 1e-300 degrees, or an origin so far out (1e300) that all texels fall on one double.
TEST_F(BadData, AGeotransformThatPlacesTheRasterNowhereIsRefused) {
  const std::pair<const char*, const char*> cases[] = {
      {"nan, 5.625, 0, 90, 0, -5.625", "not finite"},
      {"-180, inf, 0, 90, 0, -5.625", "not finite"},
      {"-180, 1e-300, 0, 90, 0, -1e-300", "finer than 1e-12 rad"},
      {"1e300, 5.625, 0, 90, 0, -5.625", "finer than 1e-12 rad"},
  };
  for (const auto& [geotransform, says] : cases) {
    const CommandResult result =
        renderHeights(write("nowhere.vrt", vrt("rasterXSize=\"64\" rasterYSize=\"32\"", "EPSG:4326", geotransform)));
    expectRefused(result, {"nowhere.vrt' has the geotransform", says, "gdal_edit.py -a_ullr"});
  }
}

TEST_F(BadData, ABrokenCrsIsRefusedNamingTheFile) {
  const CommandResult result =
      renderHeights(write("broken.vrt", vrt("rasterXSize=\"64\" rasterYSize=\"32\"",
                                            "GEOGCS[\"broken\",DATUM[\"nothing\"", kGlobalGeotransform)));
  expectRefused(result, {"broken.vrt", "no PROJ form", "projection"});
}

TEST_F(BadData, NoCrsWithAGeotransformInMetresIsRefused) {
  const CommandResult result = renderHeights(
      write("metres.vrt", vrt("rasterXSize=\"64\" rasterYSize=\"32\"", "", "-2e6, 62500, 0, 1e6, 0, -62500")));
  expectRefused(result, {"metres.vrt' has no CRS", "not degrees", "gdal_edit.py -a_srs"});
}

TEST_F(BadData, NoCrsNorGeotransformAndNot2To1AsksForAnExtent) {
  const CommandResult result = renderHeights(write("bare.vrt", vrt("rasterXSize=\"64\" rasterYSize=\"48\"", "", "")));
  expectRefused(result, {"bare.vrt' has no geotransform and is not 2:1", "extent: [west, south, east, north]"});
}

TEST_F(BadData, AColourRasterOfFloatsIsRefusedWithAFix) {
  writeFloatRaster(file("floats.tif"), 64, 32, kGlobe, blocksOf(0.5f));
  expectRefused(renderColour(file("floats.tif"), "32x18"), {"floats.tif' holds Float32", "gdal_translate -ot Byte"});
}

// A global colour raster written in `format` (PNG, JPEG) beside a world file, cut to half its length.
fs::path truncatedCopy(const fs::path& directory, const std::string& format, const std::string& extension) {
  const fs::path tiff = directory / "colour.tif", copy = directory / ("cut." + extension);
  writeColourRaster(tiff, 512, 256, {-180.0, -90.0, 180.0, 90.0}, [](int column, int row) {
    return Rgb8{static_cast<unsigned char>(column / 2), static_cast<unsigned char>(row), 90};
  });
  GDALDatasetH source = GDALOpen(tiff.c_str(), GA_ReadOnly);
  GDALDatasetH written =
      GDALCreateCopy(GDALGetDriverByName(format.c_str()), copy.c_str(), source, FALSE, nullptr, nullptr, nullptr);
  GDALClose(written);
  GDALClose(source);
  fs::resize_file(copy, fs::file_size(copy) / 2);
  return copy;
}

void expectPagesReported(const CommandResult& result, const std::string& name) {
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.err, "strata: warning: cannot read")) << result.err;
  EXPECT_TRUE(contains(result.err, name)) << result.err;
  EXPECT_TRUE(contains(result.err, "gdalinfo -checksum")) << result.err;
}

TEST_F(BadData, ATruncatedPngDrawsWithItsUnreadablePagesReported) {
  GDALAllRegister();
  expectPagesReported(renderColour(truncatedCopy(scratch_.path(), "PNG", "png"), "640x360"), "cut.png");
}

// libjpeg decodes a truncated JPEG as grey with a warning only; the warning must fail the page.
TEST_F(BadData, ATruncatedJpegDrawsWithItsUnreadablePagesReportedNotGrey) {
  GDALAllRegister();
  expectPagesReported(renderColour(truncatedCopy(scratch_.path(), "JPEG", "jpg"), "640x360"), "cut.jpg");
}

}  // namespace
}  // namespace strata::test
