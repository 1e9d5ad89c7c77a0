// A view resolved over one body of a scene as it sees another (viewOfBody): the same eye and the same rays.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <strata/camera.hpp>

namespace strata {
namespace {

// A body turned 30 degrees about z and 20 about x, as an orbit may turn it, 384,000 km away.
BodyPlacement turnedBody() {
  const double a = glm::radians(30.0), b = glm::radians(20.0);
  const glm::dmat3 aboutZ(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0);
  const glm::dmat3 aboutX(1.0, 0.0, 0.0, 0.0, std::cos(b), std::sin(b), 0.0, -std::sin(b), std::cos(b));
  return {glm::dvec3(3.844e8, -2.0e7, 1.0e7), aboutZ * aboutX};
}

// A point of the scene lies at the same place in eye space whichever body's view measures it, to a
// millimetre in 400,000 km (doubles keep 1e-16 of it: 40 nm).
TEST(ViewOfBody, EveryPointKeepsItsPlaceInEyeSpace) {
  const Body earth{"Earth", 6371000.0}, moon{"Moon", 1737400.0};
  const View seen =
      makeView(earth, Camera{.lon = 30.0, .lat = 10.0, .altitude = 5.0e8, .heading = 20.0, .tilt = 10.0}, 640, 480);
  const BodyPlacement here{}, there = turnedBody();
  const View other = viewOfBody(seen, here, there, moon);
  for (const glm::dvec3 inScene : {glm::dvec3(3.8e8, -1.9e7, 1.2e7), glm::dvec3(1.0e6, 2.0e6, -3.0e6)}) {
    const glm::dvec3 onMoon = glm::transpose(there.axes) * (inScene - there.centre);
    const glm::dvec3 a = seen.toEye(inScene), b = other.toEye(onMoon);
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-3);
  }
}

// The other body's view is measured from the point below the eye on that body, and its near plane is a
// thousandth of the way to that body's ground, as makeView places them over it.
TEST(ViewOfBody, ItsReferenceAndNearPlaneAreTheOtherBodys) {
  const Body earth{"Earth", 6371000.0}, moon{"Moon", 1737400.0};
  const BodyPlacement here{}, there = turnedBody();
  const View seen = makeView(earth, Camera{.lon = -20.0, .lat = 5.0, .altitude = 3.0e8}, 320, 240);
  const View other = viewOfBody(seen, here, there, moon);
  const glm::dvec3 eye = glm::normalize(other.eye);
  EXPECT_NEAR(other.reference.x, std::atan2(eye.y, eye.x), 1e-12);
  EXPECT_NEAR(other.reference.y, std::asin(eye.z), 1e-12);
  EXPECT_NEAR(other.near, (glm::length(other.eye) - moon.radius) * 1e-3, 1e-6);
  EXPECT_EQ(other.width, seen.width);
  EXPECT_DOUBLE_EQ(other.verticalFov, seen.verticalFov);
}

// The identity placement leaves a view as it is.
TEST(ViewOfBody, TheSameBodySeesTheSameView) {
  const Body earth{"Earth", 6371000.0};
  const View seen = makeView(earth, Camera{.lon = 137.0, .lat = -35.0, .altitude = 2.0}, 100, 100);
  const View same = viewOfBody(seen, {}, {}, earth);
  EXPECT_EQ(same.eye, seen.eye);
  EXPECT_NEAR(same.near, seen.near, 1e-12);
  EXPECT_NEAR(same.reference.x, seen.reference.x, 1e-12);
  EXPECT_NEAR(same.reference.y, seen.reference.y, 1e-12);
}

}  // namespace
}  // namespace strata
