// composite.overlay_mask (issue 7; seed 000 section 4.2): a red overlay of 80 x 80 texels (20 x 20 degrees
// from longitude 0) over a blue global base, seen straight down over its west edge, where a texel spans about
// 4 pixels. Along the image's middle row the overlay's weight w (its share of the red, from the pixels far
// either side) rises from 0 to 1 across the edge: at once for a hard edge (the raster's extent is where its
// coverage stops), and from 0 at the edge to 1 half the feather inside for a feathered one, in texels or in
// metres alike: 0.1 to 0.9 over 0.8 x 8 texels x about 4 pixels, some 26 pixels. Measured on llvmpipe: 0
// pixels hard, 22 feathered over 16 texels and 22 over the same width in metres.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 240;

// A one-colour RGB GeoTIFF of width x height texels over [west, north] to [east, south] degrees.
void writeColour(const std::filesystem::path& file, std::array<double, 4> extent, int width, int height,
                 std::array<unsigned char, 3> colour) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(
      GetGDALDriverManager()->GetDriverByName("GTiff")->Create(file.c_str(), width, height, 3, GDT_Byte, nullptr));
  OGRSpatialReference crs;
  crs.SetFromUserInput("+proj=longlat +R=3396190");
  dataset->SetSpatialRef(&crs);
  std::array<double, 6> t{extent[0], (extent[2] - extent[0]) / width, 0.0, extent[3], 0.0, (extent[1] - extent[3]) / height};
  dataset->SetGeoTransform(t.data());
  std::vector<unsigned char> band(std::size_t(width) * height);
  for (int b = 0; b < 3; ++b) {
    std::fill(band.begin(), band.end(), colour[std::size_t(b)]);
    ASSERT_EQ(dataset->GetRasterBand(b + 1)->RasterIO(GF_Write, 0, 0, width, height, band.data(), width, height,
                                                       GDT_Byte, 0, 0),
              CE_None);
  }
}

std::string pipeline(const std::filesystem::path& directory, const std::string& edge) {
  return "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
         "camera: {lon: 0, lat: 0, altitude: 1.2e6, fov: 45}\n"
         "nodes:\n"
         "  base: {type: source.gdal, path: " + (directory / "base.tif").string() + "}\n"
         "  overlay: {type: source.gdal, path: " + (directory / "overlay.tif").string() + "}\n"
         "  laid: {type: composite.overlay_mask, base: base, overlay: overlay" + edge + "}\n"
         "  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [laid], shading: none}\n";
}

// The pixels of the middle row over which the overlay's weight rises from 0.1 to 0.9.
int edgeWidth(const Image& image) {
  const int y = kSize / 2;
  const double outside = image.at(10, y)[0], inside = image.at(kSize - 10, y)[0];
  EXPECT_GT(inside - outside, 100.0) << "red overlay east of the middle, blue base west of it";
  int first = -1, last = -1;
  for (int x = 0; x < kSize; ++x) {
    const double w = (image.at(x, y)[0] - outside) / (inside - outside);
    if (first < 0 && w > 0.1) first = x;
    if (last < 0 && w >= 0.9) last = x;
  }
  return last - first;
}

TEST(OverlayMask, EdgesAreHardOrFeatheredAsAsked) {
  TemporaryDirectory directory;
  writeColour(directory.path() / "base.tif", {-180.0, -90.0, 180.0, 90.0}, 360, 180, {40, 60, 200});
  writeColour(directory.path() / "overlay.tif", {0.0, -10.0, 20.0, 10.0}, 80, 80, {220, 40, 30});
  auto engine = makeEngine();
  const auto widthOf = [&](const std::string& edge) {
    const Image image = renderFrame(*engine, directory.write("laid.yaml", pipeline(directory.path(), edge)), kSize, kSize);
    const int width = edgeWidth(image);
    std::printf("edge%s: weight 0.1 to 0.9 over %d pixels\n", edge.c_str(), width);
    return width;
  };
  const int hard = widthOf("");
  const int texels = widthOf(", feather: 16");
  const int metres = widthOf(", feather: 237100, feather_units: metres");  // 16 texels of 0.25 degrees
  EXPECT_LE(hard, 2) << "a step";
  EXPECT_GE(texels, 15) << "0.8 of half of 16 texels is some 26 pixels";
  EXPECT_LE(texels, 40);
  EXPECT_NEAR(metres, texels, 0.2 * texels + 2) << "the same feather given in metres";
}

}  // namespace
}  // namespace strata::test
