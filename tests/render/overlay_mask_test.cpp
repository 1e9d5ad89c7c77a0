// composite.overlay_mask (issue 7; [Kooima 2008, §4.2]): a red overlay over a blue global base, seen straight
// down over an edge of the overlay in the middle of the frame. Along the image's middle row the overlay's
// weight w (its share of the red, from the pixels far either side) rises from 0 to 1 across the edge: at once
// for a hard edge, and from 0 at the edge to 1 some distance inside for a feathered one.
//
// EdgesAreHardOrFeatheredAsAsked: an overlay of 80 x 80 texels (20 x 20 degrees from longitude 0), its west
// edge the raster's extent, a texel about 4 pixels: for a feather of 16 texels, 0.1 to 0.9 over 0.8 x 8
// texels x about 4 pixels, some 26 pixels; in texels or in metres alike. Measured on llvmpipe: 0 pixels hard,
// 22 feathered over 16 texels and 22 over the same width in metres.
//
// The other tests look closer (42 km up, an overlay texel of 0.0098 degrees, 579 m, about 4 pixels) at an
// edge at longitude 0 of another kind each: the extent of an overlay, its nodata (its west part), a mask
// raster (0 west, 1 east), a polygon from a GeoJSON file, the same polygon in metres (a GeoPackage in
// equidistant cylindrical). Their overlays and masks are 4096 texels wide, so that a feather of 8 texels
// finds its averaged coverage in their pyramids (it averages over half its width, level 2's 4 x 4 texels; a
// layer's coarsest level is its first of one page, 512 texels). Tolerances:
// - each edge lies where its data say: hard, the middle of the step within 2 pixels of the middle column
//   (120); feathered, the ramp's start, since a feather fades in from the edge inwards;
// - hard, the weight rises from 0.1 to 0.9 within 4 pixels: a texel's bilinear filter of the coverage (0.8 of
//   a texel) at nodata and mask edges, 0 at the extent, which is clipped;
// - feathered, at least 6 pixels (not a step), and as wide as across the overlay's extent within half that
//   plus 2 pixels: the extent's ramp is the distance to the raster's edge over half the width (0.8 x 4
//   texels x 4 pixels = 13), the others the averaged coverage, which reaches 1 between a quarter and the
//   whole of the width as the edge falls in the coarse levels' texels.
// Measured on llvmpipe: extent 12 pixels; nodata 3 hard, 8 feathered; raster mask 3 and 8; polygon mask 3
// and 12, in degrees and in metres alike; every edge at pixels 118 to 122. The nodata and raster-mask edges
// lie in the middle of texels of every coarser level: there GDAL's own reductions (a nodata mask to "any
// valid", 0/1 bytes rounded) made steps of them, which source.gdal now refines (raster_reading.cpp).
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 240;
constexpr std::array<unsigned char, 3> kRed{220, 40, 30};
constexpr std::array<unsigned char, 3> kBlue{40, 60, 200};

std::unique_ptr<GDALDataset> createRaster(const std::filesystem::path& file, std::array<double, 4> extent, int width,
                                          int height, int bands) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(
      GetGDALDriverManager()->GetDriverByName("GTiff")->Create(file.c_str(), width, height, bands, GDT_Byte, nullptr));
  OGRSpatialReference crs;
  crs.SetFromUserInput("+proj=longlat +R=3396190");
  dataset->SetSpatialRef(&crs);
  std::array<double, 6> t{extent[0], (extent[2] - extent[0]) / width, 0.0, extent[3],
                          0.0,       (extent[1] - extent[3]) / height};
  dataset->SetGeoTransform(t.data());
  return dataset;
}

// Band `band` of `dataset`: `west` in the columns before `firstEast`, `east` from there on.
void writeHalves(GDALDataset& dataset, int band, int firstEast, unsigned char west, unsigned char east) {
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  std::vector<unsigned char> values(std::size_t(width) * height);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = int(i % std::size_t(width)) < firstEast ? west : east;
  ASSERT_EQ(dataset.GetRasterBand(band)->RasterIO(GF_Write, 0, 0, width, height, values.data(), width, height, GDT_Byte,
                                                  0, 0),
            CE_None);
}

// A one-colour RGB GeoTIFF of width x height texels over [west, south, east, north] degrees; with
// `firstData`, nodata (0) in the columns before it.
void writeColour(const std::filesystem::path& file, std::array<double, 4> extent, int width, int height,
                 std::array<unsigned char, 3> colour, int firstData = 0) {
  const std::unique_ptr<GDALDataset> dataset = createRaster(file, extent, width, height, 3);
  for (int b = 0; b < 3; ++b) {
    if (firstData > 0) dataset->GetRasterBand(b + 1)->SetNoDataValue(0.0);
    writeHalves(*dataset, b + 1, firstData, 0, colour[std::size_t(b)]);
  }
}

// A one-band mask raster: 0 west of column `firstEast`, 1 from there on.
void writeMask(const std::filesystem::path& file, std::array<double, 4> extent, int width, int height, int firstEast) {
  writeHalves(*createRaster(file, extent, width, height, 1), 1, firstEast, 0, 1);
}

std::string source(const std::string& name, const std::filesystem::path& file, const std::string& more = "") {
  return "  " + name + ": {type: source.gdal, path: " + file.string() + more + "}\n";
}

// The base, the `sources` (the overlay, any mask) and the overlay laid over the base with `laid` said of it.
std::string pipeline(const std::filesystem::path& directory, double altitude, const std::string& sources,
                     const std::string& laid) {
  return "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
         "camera: {lon: 0, lat: 0, altitude: " +
         std::to_string(altitude) +
         ", fov: 45}\n"
         "nodes:\n" +
         source("base", directory / "base.tif") + sources +
         "  laid: {type: composite.overlay_mask, base: base, overlay: overlay" + laid +
         "}\n"
         "  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [laid], shading: none}\n";
}

// Where along the middle row the overlay's weight rises from 0.1 (first) to 0.9 (last).
struct Ramp {
  int first = -1;
  int last = -1;
  int width() const { return last - first; }
};

Ramp rampAcross(const Image& image) {
  const int y = kSize / 2;
  const double outside = image.at(10, y)[0], inside = image.at(kSize - 10, y)[0];
  EXPECT_GT(inside - outside, 100.0) << "red overlay east of the middle, blue base west of it";
  Ramp ramp;
  for (int x = 0; x < kSize; ++x) {
    const double w = (image.at(x, y)[0] - outside) / (inside - outside);
    if (ramp.first < 0 && w > 0.1) ramp.first = x;
    if (ramp.last < 0 && w >= 0.9) ramp.last = x;
  }
  return ramp;
}

class OverlayMask : public ::testing::Test {
 protected:
  void SetUp() override { writeColour(directory_.path() / "base.tif", {-180.0, -90.0, 180.0, 90.0}, 360, 180, kBlue); }

  Ramp rampOf(const std::string& what, double altitude, const std::string& sources, const std::string& laid) {
    const std::string text = pipeline(directory_.path(), altitude, sources, laid);
    const Image image = renderFrame(*engine_, directory_.write("laid.yaml", text), kSize, kSize);
    const Ramp ramp = rampAcross(image);
    std::printf("%s%s: weight 0.1 to 0.9 from pixel %d to %d, over %d\n", what.c_str(), laid.c_str(), ramp.first,
                ramp.last, ramp.width());
    return ramp;
  }

  std::filesystem::path file(const std::string& name) const { return directory_.path() / name; }

  // The ramp across an overlay's own west edge at longitude 0, close up and feathered by 8 texels: what the
  // other kinds of edge are measured against.
  Ramp extentRamp();

  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_ = makeEngine();
};

TEST_F(OverlayMask, EdgesAreHardOrFeatheredAsAsked) {
  writeColour(file("overlay.tif"), {0.0, -10.0, 20.0, 10.0}, 80, 80, kRed);
  const std::string overlay = source("overlay", file("overlay.tif"));
  const int hard = rampOf("extent", 1.2e6, overlay, "").width();
  const int texels = rampOf("extent", 1.2e6, overlay, ", feather: 16").width();
  // 16 texels of 0.25 degrees
  const int metres = rampOf("extent", 1.2e6, overlay, ", feather: 237100, feather_units: metres").width();
  EXPECT_LE(hard, 2) << "a step";
  EXPECT_GE(texels, 15) << "0.8 of half of 16 texels is some 26 pixels";
  EXPECT_LE(texels, 40);
  EXPECT_NEAR(metres, texels, 0.2 * texels + 2) << "the same feather given in metres";
}

// The close view of the other tests: 42 km up, overlays and masks of 4096 x 1024 texels over 40 x 10 degrees.
constexpr double kClose = 4.2e4;
constexpr int kWide = 4096;
constexpr int kHigh = 1024;
constexpr double kTexel = 40.0 / kWide;
// Longitude 0 at column 2051 of these, so that the edge there lies inside the texels of every coarser level
// (GDAL's averages of a nodata mask or of 0/1 bytes would make steps of it, ramps only where it is aligned).
constexpr int kMiddleColumn = 2051;
constexpr std::array<double, 4> kAcrossTheMiddle{-kMiddleColumn * kTexel, -5.0, 40.0 - kMiddleColumn* kTexel, 5.0};
constexpr const char* kFeather = ", feather: 8";

Ramp OverlayMask::extentRamp() {
  writeColour(file("east.tif"), {0.0, -5.0, 40.0, 5.0}, kWide, kHigh, kRed);
  const Ramp extent = rampOf("extent", kClose, source("overlay", file("east.tif")), kFeather);
  EXPECT_NEAR(extent.first, kSize / 2, 2) << "the extent's edge in the middle, the weight 0 there";
  return extent;
}

// An edge at longitude 0: hard, a step there, as steep as the bilinear filter of a texel of coverage makes it
// (0.8 of 4 pixels); feathered, a ramp from there inwards like the extent's.
void expectEdgeAtTheMiddle(const Ramp& hard, const Ramp& feathered, const Ramp& extent) {
  EXPECT_LE(hard.width(), 4) << "a step";
  EXPECT_NEAR(0.5 * (hard.first + hard.last), kSize / 2, 2) << "the edge at longitude 0, in the middle";
  EXPECT_NEAR(feathered.first, kSize / 2, 2) << "fading in from the edge";
  EXPECT_GE(feathered.width(), 6) << "a ramp, not a step";
  EXPECT_NEAR(feathered.width(), extent.width(), 0.5 * extent.width() + 2) << "as across the overlay's extent";
}

TEST_F(OverlayMask, FeathersAlongNodataAsAlongTheExtent) {
  const Ramp extent = extentRamp();
  writeColour(file("half.tif"), kAcrossTheMiddle, kWide, kHigh, kRed, kMiddleColumn);
  const std::string overlay = source("overlay", file("half.tif"));
  expectEdgeAtTheMiddle(rampOf("nodata", kClose, overlay, ""), rampOf("nodata", kClose, overlay, kFeather), extent);
}

TEST_F(OverlayMask, ARasterMaskCutsTheOverlayWhereItSays) {
  const Ramp extent = extentRamp();
  writeColour(file("overlay.tif"), kAcrossTheMiddle, kWide, kHigh, kRed);
  writeMask(file("mask.tif"), kAcrossTheMiddle, kWide, kHigh, kMiddleColumn);
  const std::string sources = source("overlay", file("overlay.tif")) + source("cut", file("mask.tif"), ", kind: mask");
  expectEdgeAtTheMiddle(rampOf("raster mask", kClose, sources, ", mask: cut"),
                        rampOf("raster mask", kClose, sources, std::string(", mask: cut") + kFeather), extent);
}

// A GeoJSON rectangle east of longitude 0, burnt into a mask of 4096 texels across its 40 degrees: texels the
// size of the overlay's.
TEST_F(OverlayMask, APolygonMaskCutsTheOverlayWhereItSays) {
  const Ramp extent = extentRamp();
  writeColour(file("overlay.tif"), kAcrossTheMiddle, kWide, kHigh, kRed);
  directory_.write("cut.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature",
    "properties": {}, "geometry": {"type": "Polygon",
    "coordinates": [[[0, -4], [40, -4], [40, 4], [0, 4], [0, -4]]]}}]})");
  const std::string sources =
      source("overlay", file("overlay.tif")) + source("cut", file("cut.geojson"), ", kind: mask, texels: 4096");
  expectEdgeAtTheMiddle(rampOf("polygon mask", kClose, sources, ", mask: cut"),
                        rampOf("polygon mask", kClose, sources, std::string(", mask: cut") + kFeather), extent);
}

// The same rectangle in a GeoPackage, in equidistant cylindrical metres: a polygon masks in its layer's CRS.
void writeRectangleInMetres(const std::filesystem::path& file) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(
      GetGDALDriverManager()->GetDriverByName("GPKG")->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  OGRSpatialReference crs;
  crs.SetFromUserInput("+proj=eqc +R=3396190");
  OGRLayer* layer = dataset->CreateLayer("cut", &crs, wkbPolygon);
  const double degree = 3396190.0 * std::numbers::pi / 180.0;  // metres of a degree along the equator
  OGRLinearRing ring;
  for (const auto& [lon, lat] : std::vector<std::pair<double, double>>{{0, -4}, {40, -4}, {40, 4}, {0, 4}, {0, -4}})
    ring.addPoint(lon * degree, lat * degree);
  OGRPolygon rectangle;
  rectangle.addRing(&ring);
  OGRFeature feature(layer->GetLayerDefn());
  feature.SetGeometry(&rectangle);
  ASSERT_EQ(layer->CreateFeature(&feature), OGRERR_NONE);
}

TEST_F(OverlayMask, APolygonInProjectedMetresCutsAlike) {
  const Ramp extent = extentRamp();
  writeColour(file("overlay.tif"), kAcrossTheMiddle, kWide, kHigh, kRed);
  writeRectangleInMetres(file("cut.gpkg"));
  const std::string sources =
      source("overlay", file("overlay.tif")) + source("cut", file("cut.gpkg"), ", kind: mask, texels: 4096");
  expectEdgeAtTheMiddle(rampOf("projected polygon", kClose, sources, ", mask: cut"),
                        rampOf("projected polygon", kClose, sources, std::string(", mask: cut") + kFeather), extent);
}

}  // namespace
}  // namespace strata::test
