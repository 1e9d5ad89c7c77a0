// Anisotropic filtering by hand (shaders/strata/anisotropic_taps.glsl) at the pole of a global map. A 4096 x 2048
// equirectangular raster of latitude rings, black and white, each 4 texels (0.35 degrees) wide, seen straight
// down from 2,000 km over lat 84, lon 30. There a pixel spans some 6 texels of longitude and 0.7 of latitude:
// trilinear filtering at the longer axis blurs the rings into grey, the taps along it keep them. Each pixel
// whose footprint (its four corners' rays, met with the sphere in double) lies within one ring is judged: right
// where its light keeps within a quarter of the ring's, over 0.75 on white and under 0.25 on black (linear).
//
// Measured on llvmpipe: 98.4% of the judged pixels right with the taps; with one trilinear tap at the
// footprint's longer axis (kAnisotropicTaps 1), 60.4%. Tolerance: 95% right, room for pixels whose ring edge
// the mesh's chords move across a corner.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "srgb.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 256;
constexpr int kWidth = 4096, kHeight = 2048;
constexpr int kRingTexels = 4;
constexpr double kEarth = 6371000.0;

// The ring (row of rings from the north pole) at latitude `lat` (deg).
int ringAt(double lat) { return int(std::floor((90.0 - lat) / 180.0 * kHeight / kRingTexels)); }

// The ring all of pixel (x, y) lies in, from the rays through its corners; -1 where it spans more than one.
int ringUnder(const View& view, int x, int y) {
  int ring = -1;
  for (const double dx : {-0.5, 0.5})
    for (const double dy : {-0.5, 0.5}) {
      const auto hit = raycastSphere(view, kEarth, x + dx, y + dy);
      if (!hit) return -1;
      const int here = ringAt(hit->lat);
      if (ring >= 0 && here != ring) return -1;
      ring = here;
    }
  return ring;
}

TEST(AnisotropicFiltering, LatitudeRingsStaySharpNearThePole) {
  TemporaryDirectory directory;
  writeColourRaster(directory.path() / "rings.tif", kWidth, kHeight, {-180, -90, 180, 90}, [](int, int row) {
    const unsigned char level = (row / kRingTexels) % 2 == 0 ? 255 : 0;
    return Rgb8{level, level, level};
  });
  const auto pipeline =
      directory.write("rings.yaml",
                      "strata: 1\nbody: {name: Earth, radius: 6371000}\nnodes:\n"
                      "  rings: {type: source.gdal, path: " +
                          (directory.path() / "rings.tif").string() +
                          "}\n  globe: {type: geometry.icosahedral}\n"
                          "  frame: {type: output.image, geometry: globe, surface: [rings], shading: none}\n");
  auto engine = makeEngine();
  engine->load(pipeline);
  const Camera camera{.lon = 30, .lat = 84, .altitude = 2.0e6, .fov = 45};
  const Image image = renderFrames(*engine, camera, kSize, kSize, 1);
  const View view = engine->view(kSize, kSize);
  int judged = 0, right = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int ring = ringUnder(view, x, y);
      if (ring < 0) continue;
      ++judged;
      const double light = linearLightOf(image.at(x, y)[1]);
      right += ring % 2 == 0 ? light > 0.75 : light < 0.25;
    }
  std::printf("%d pixels judged, %.1f%% right\n", judged, 100.0 * right / std::max(judged, 1));
  EXPECT_GT(judged, kSize * kSize / 4);
  EXPECT_GE(right, 0.95 * judged);
}

}  // namespace
}  // namespace strata::test
