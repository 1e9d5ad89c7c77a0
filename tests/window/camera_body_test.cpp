// The scene panel's "camera over" list: the camera moved to another body of the scene keeps its direction and
// frames the new body as it framed the old.
#include <gtest/gtest.h>

#include <strata/viewer/scene_panel.hpp>

namespace strata::viewer {
namespace {

TEST(CameraOverBody, KeepsTheDirectionAndTheDistanceInRadii) {
  const Body earth{"Earth", 6371000.0}, moon{"Moon", 1737400.0};
  const Camera overEarth{.lon = 30.0, .lat = -10.0, .altitude = 6371000.0, .heading = 45.0, .tilt = 20.0, .fov = 35.0};
  const Camera overMoon = cameraOverBody(overEarth, earth, moon, "moon");
  EXPECT_EQ(overMoon.body, "moon");
  EXPECT_DOUBLE_EQ(overMoon.altitude, 1737400.0);  // two radii from the centre, as over the Earth
  EXPECT_EQ(overMoon.lon, overEarth.lon);
  EXPECT_EQ(overMoon.lat, overEarth.lat);
  EXPECT_EQ(overMoon.heading, overEarth.heading);
  EXPECT_EQ(overMoon.tilt, overEarth.tilt);
  EXPECT_EQ(overMoon.fov, overEarth.fov);
  const Camera back = cameraOverBody(overMoon, moon, earth, "earth");
  EXPECT_NEAR(back.altitude, overEarth.altitude, 1e-6);
}

}  // namespace
}  // namespace strata::viewer
