// An eye below the ground it looks at, on real data: the EGM96 geoid (proj-data's 15' grid, 1440 x 721
// texels whose centres lie on the poles, so that its edges lie half a texel beyond them) exaggerated 2000
// times stands 53 km at lon 10, lat 20, and the peer benchmark's view (c) looks from 5 km, tilted 60
// degrees. Each patch bounds its heights by the blocks of the raster it covers; when the blocks along the
// poles, whose edges no projection places, were taken to cover the whole body, every patch reached from
// -59 km to +57 km, held the eye, lay at no distance and split to the deepest level: 3,957 patches where
// `patches` allows 300. Now the patches near the eye lie well above it, and the tree keeps within the cap,
// as it does from orbit.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kPatches = 300;  // geometry.icosahedral's default cap

TEST(EyeBelowTheGround, TheTreeKeepsWithinItsCapUnderAnExaggeratedGeoid) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  engine->load(directory.write("geoid.yaml",
                               "strata: 1\nbody: {name: Earth, radius: 6371000}\nnodes:\n"
                               "  geoid: {type: source.gdal, path: /usr/share/proj/egm96_15.gtx, kind: height, "
                               "scale: 2000}\n"
                               "  imagery: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, "
                               "kind: color}\n"
                               "  terrain: {type: geometry.icosahedral, height: geoid}\n"
                               "  frame: {type: output.image, geometry: terrain, surface: [imagery], "
                               "antialiasing: none}\n"));
  for (const Camera& camera : {Camera{.lon = 10, .lat = 20, .altitude = 5000, .tilt = 60, .fov = 36},
                               Camera{.lon = 10, .lat = 20, .altitude = 2.0e7, .fov = 36}}) {
    renderFrames(*engine, camera, 320, 180, 1);
    const int patches = engine->geometryStatistics().patches;
    std::printf("%.0f m up: %d patches\n", camera.altitude, patches);
    EXPECT_GT(patches, 0);
    EXPECT_LE(patches, kPatches);
  }
}

}  // namespace
}  // namespace strata::test
