// When the least visible height of one view may stand for another (visible_radius.hpp's sameSight): while
// the eye moves by under kSightMove of its height above the minimum sphere and turns by under kSightTurn of
// the field of view, on a frame of the same size.
#include <gtest/gtest.h>

#include "visible_radius.hpp"

namespace strata::pgm {
namespace {

constexpr double kRadius = 6371000.0;  // m
const Body kEarth{.name = "Earth", .radius = kRadius};
const Camera kCamera{.lon = 12.0, .lat = 47.0, .altitude = 1000.0, .heading = 30.0, .tilt = 60.0, .fov = 50.0};
constexpr double kMinimum = kRadius - 500.0;  // m: the sphere 1500 m below the eye

View viewFrom(const Camera& camera) { return makeView(kEarth, camera, 320, 240); }

TEST(PgmSameSight, AViewStandsForItself) { EXPECT_TRUE(sameSight(viewFrom(kCamera), viewFrom(kCamera), kMinimum)); }

TEST(PgmSameSight, TheEyeMayMoveByAShareOfItsHeight) {
  for (const double metres : {0.04 * 1500.0, 0.06 * 1500.0}) {
    Camera moved = kCamera;
    moved.altitude += metres;
    EXPECT_EQ(sameSight(viewFrom(kCamera), viewFrom(moved), kMinimum), metres < kSightMove * 1500.0) << metres;
  }
}

TEST(PgmSameSight, TheViewMayTurnByAShareOfItsFieldOfView) {
  for (const double share : {0.04, 0.06}) {
    Camera turned = kCamera;
    turned.heading += share * kCamera.fov;
    EXPECT_EQ(sameSight(viewFrom(kCamera), viewFrom(turned), kMinimum), share < kSightTurn) << share;
  }
}

TEST(PgmSameSight, AnotherFrameSizeOrFieldOfViewDoesNot) {
  Camera wider = kCamera;
  wider.fov = 51.0;
  EXPECT_FALSE(sameSight(viewFrom(kCamera), viewFrom(wider), kMinimum));
  EXPECT_FALSE(sameSight(viewFrom(kCamera), makeView(kEarth, kCamera, 640, 480), kMinimum));
}

}  // namespace
}  // namespace strata::pgm
