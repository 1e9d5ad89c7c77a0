// The viewer's navigation (issue 9: "from 100,000 km down to 1 m above the ground and back without a
// jump"): the wheel's steps scale the altitude by the same factor all the way, the point below the eye
// stays put while zooming, and a drag moves the ground under the pointer by about as much at any altitude.
#include <gtest/gtest.h>

#include <cmath>

#include <strata/viewer/orbit_controls.hpp>

namespace strata::test {
namespace {

TEST(OrbitControls, ZoomsFrom100000KmToAMetreAndBackInEvenSteps) {
  const Body earth{"Earth", 6371000.0};
  Camera camera{.lon = 10, .lat = 20, .altitude = 1.0e8};
  viewer::OrbitControls controls(earth, camera);
  int steps = 0;
  for (double before = camera.altitude; camera.altitude > 1.0; before = camera.altitude, ++steps) {
    controls.scroll(1.0);
    if (camera.altitude > 1.0) {  // the last step clamps
      EXPECT_NEAR(camera.altitude / before, 0.85, 1e-12);
    }
  }
  EXPECT_EQ(camera.altitude, 1.0) << "a metre above the ground, and no lower";
  EXPECT_EQ(steps, 114) << "log(1e8) / log(1 / 0.85) steps";
  for (int i = 0; i < steps; ++i) controls.scroll(-1.0);
  EXPECT_NEAR(camera.altitude, 1.0e8, 1.0e8 * 0.15) << "back out, the same steps (the last one in was clamped)";
  EXPECT_EQ(camera.lon, 10.0);
  EXPECT_EQ(camera.lat, 20.0);
}

// A drag of the viewport's height moves the ground under the pointer by about the view's height there.
TEST(OrbitControls, ADragMovesTheGroundAlikeAtAnyAltitude) {
  const Body earth{"Earth", 6371000.0};
  for (const double altitude : {1.0, 1.0e3, 1.0e6}) {
    Camera camera{.lon = 0, .lat = 0, .altitude = altitude, .fov = 45};
    viewer::OrbitControls(earth, camera).drag(0.0, 100.0, 0, 100);
    const double moved = camera.lat * M_PI / 180.0 * earth.radius;
    EXPECT_NEAR(moved / (2.0 * altitude * std::tan(M_PI / 8.0)), 1.0, 1e-9) << altitude;
  }
}

}  // namespace
}  // namespace strata::test
