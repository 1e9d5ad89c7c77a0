// geometry.icosahedral leaves no cracks where patches of different levels meet: rendered from low and
// tilted views, where the patch tree spans many levels, every pixel whose ray meets the body is drawn.
#include <gtest/gtest.h>

#include <string>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 320, kHeight = 240;

struct LowView {
  double lon;       // deg
  double lat;       // deg
  double altitude;  // m
  double tilt;      // deg
  bool heights;     // displaced by source.procedural's heights
};

class LevelBoundaries : public ::testing::TestWithParam<LowView> {};

// The body, unlit and without surface layers, is the empty grey (sRGB 118) and space is black: a crack
// shows as a black pixel. With heights, a vertex two patches share must be displaced alike in both.
TEST_P(LevelBoundaries, EveryPixelOnTheBodyIsDrawn) {
  TemporaryDirectory directory;
  const LowView low = GetParam();
  const auto pipeline = directory.write(
      "low.yaml",
      "strata: 1\ncamera: {lon: " + std::to_string(low.lon) + ", lat: " + std::to_string(low.lat) + ", altitude: " +
          std::to_string(low.altitude) + ", heading: 20, tilt: " + std::to_string(low.tilt) + "}\nnodes:\n" +
          (low.heights ? "  heights: {type: source.procedural, kind: height}\n"
                         "  globe: {type: geometry.icosahedral, height: heights, lowest: -12000, highest: 12000}\n"
                       : "  globe: {type: geometry.icosahedral}\n") +
          "  frame: {type: output.image, geometry: globe, shading: none}\n");
  auto engine = makeEngine();
  const Image image = renderFrame(*engine, pipeline, kWidth, kHeight);
  const View view = engine->view(kWidth, kHeight);
  const double radius = engine->pipeline().body.radius;
  int onBody = 0, cracks = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      // Pixels within two of the limb are left out: there the rasterised chords lie inside the sphere.
      bool inside = true;
      for (int dy = -2; dy <= 2 && inside; ++dy)
        for (int dx = -2; dx <= 2 && inside; ++dx) inside = raycastSphere(view, radius, x + dx, y + dy).has_value();
      if (!inside) continue;
      ++onBody;
      if (image.at(x, y)[1] == 0) ++cracks;
    }
  EXPECT_GT(onBody, kWidth * kHeight / 4);
  EXPECT_EQ(cracks, 0) << "background pixels through the surface, of " << onBody;
}

// From a person's height looking ahead to a high flight: the tree spans some ten levels in each.
// Across the date line from a person's height up to a high flight, then over relief (up to 12 km) as the
// fly-in benchmark descends, to its end 300 m above the summit, where the one-level rule's forced splits
// and geomorphing are busiest. The T-junctions of patches drawn without their edge windings crack the
// first two; heights sampled with each patch's own footprint left a dozen one-pixel holes in the fifth.
INSTANTIATE_TEST_SUITE_P(
    Views, LevelBoundaries,
    ::testing::Values(LowView{179.99, 35.0, 2.0, 80.0, false}, LowView{179.99, 35.0, 500.0, 85.0, false},
                      LowView{179.99, 35.0, 2.0e4, 70.0, false}, LowView{179.99, 35.0, 1.0e6, 40.0, false},
                      LowView{10.0, 20.0, 3.0e4, 60.0, true}, LowView{-74.0, 4.0, 1.0e5, 30.0, true},
                      LowView{-74.0, 4.0, 1.5e4, 60.0, true}, LowView{-74.0, 3.98, 9.0e3, 75.0, true}),
    [](const ::testing::TestParamInfo<LowView>& view) {
      return "altitude_" + std::to_string(int(view.param.altitude)) + "m_tilt_" + std::to_string(int(view.param.tilt)) +
             (view.param.heights ? "_heights" : "");
    });

}  // namespace
}  // namespace strata::test
