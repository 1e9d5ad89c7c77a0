// A global raster seen up close at the antimeridian is drawn from its finest pages on both sides. The page
// across the seam from the eye has its nearest point on its edge, between two of its sample points (45
// degrees apart on a page of the middle level), and was taken for one below the horizon: that side was
// drawn from a coarser level, a hard vertical seam at lon 180 (seen on xplanet's earth.jpg 30 km up).
//
// The raster is dark but for its two seam columns, bright: at full resolution the middle of the view, within
// half a texel of the seam, is bright on both sides; from the next level, which averages each seam column
// with a dark neighbour, a side would be about half as bright.
#include <gtest/gtest.h>

#include <string>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kTexelsAcross = 2048, kTexelsDown = 1024;  // 4 x 2 pages at full resolution, 3 levels
constexpr unsigned char kBright = 200, kDark = 40;
constexpr int kSize = 256;

TEST(AntimeridianPages, BothSidesOfTheSeamAreDrawnAtFullResolution) {
  TemporaryDirectory directory;
  writeColourRaster(directory.path() / "seam.tif", kTexelsAcross, kTexelsDown, {-180, -90, 180, 90},
                    [](int column, int) {
                      const unsigned char grey = column == 0 || column == kTexelsAcross - 1 ? kBright : kDark;
                      return Rgb8{grey, grey, grey};
                    });
  // 30 km up at 65.5 N, the view is 25 km across: half a texel (0.088 degrees, 4 km there) either side of
  // the seam is 41 pixels.
  const auto pipeline =
      directory.write("seam.yaml",
                      "strata: 1\ncamera: {lon: 180, lat: 65.5, altitude: 30000, fov: 45}\nnodes:\n"
                      "  imagery: {type: source.gdal, path: seam.tif}\n"
                      "  globe: {type: geometry.icosahedral}\n"
                      "  frame: {type: output.image, geometry: globe, surface: [imagery], shading: none}\n");
  auto engine = makeEngine();
  const Image image = renderFrame(*engine, pipeline, kSize, kSize);
  int dim = 0;
  for (int y = 0; y < kSize; y += 8)
    for (int x = kSize / 2 - 30; x < kSize / 2 + 30; ++x) dim += image.at(x, y)[1] < kBright - 8;
  EXPECT_EQ(dim, 0) << "pixels within half a texel of the seam darker than the seam columns";
}

}  // namespace
}  // namespace strata::test
