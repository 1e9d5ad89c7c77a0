// makeView turns a user's camera into the eye position and axes, in double precision.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <strata/camera.hpp>

namespace strata {
namespace {

constexpr double kTolerance = 1e-12;  // unit vectors built from a few trigonometric calls in double

glm::dvec3 forwardOf(const View& view) { return -glm::transpose(view.planetToEye)[2]; }
glm::dvec3 upOf(const View& view) { return glm::transpose(view.planetToEye)[1]; }

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], kTolerance) << "component " << i;
}

TEST(MakeView, EyeIsAboveTheCameraPoint) {
  const Body body{"Mars", 3389500.0};
  const View view = makeView(body, Camera{.lon = 137.4, .lat = -4.6, .altitude = 250.0}, 800, 600);
  expectNear(glm::normalize(view.eye), unitNormal(glm::radians(137.4), glm::radians(-4.6)));
  EXPECT_NEAR(glm::length(view.eye), 3389750.0, 1e-6);  // m: radius plus altitude, exact in double
}

TEST(MakeView, TiltZeroLooksStraightDownWithNorthUp) {
  const View view = makeView(Body{}, Camera{.lon = 10, .lat = 20, .altitude = 1e6}, 640, 480);
  expectNear(forwardOf(view), -unitNormal(glm::radians(10.0), glm::radians(20.0)));
  EXPECT_GT(upOf(view).z, 0.0) << "north is at the top of the image";
}

TEST(MakeView, HeadingAndTiltTurnTheViewTowardTheHorizon) {
  // Heading 90 at the equator and prime meridian faces east (+y); tilt 90 looks along the horizon.
  const View view = makeView(Body{}, Camera{.lon = 0, .lat = 0, .altitude = 1e3, .heading = 90, .tilt = 90}, 640, 480);
  expectNear(forwardOf(view), glm::dvec3(0, 1, 0));
  expectNear(upOf(view), glm::dvec3(1, 0, 0));
}

// At a 90-degree vertical field of view the frame's top edge lies at 45 degrees: tangent 1; across, as much
// again as the frame is wider than high.
TEST(MakeView, HalfFrameTangentsBoundTheFrameAtUnitDistance) {
  const View view = makeView(Body{}, Camera{.altitude = 1e6, .fov = 90}, 1280, 720);
  EXPECT_NEAR(view.halfFrameTangents().y, 1.0, kTolerance);
  EXPECT_NEAR(view.halfFrameTangents().x, 1280.0 / 720.0, kTolerance);
}

TEST(MakeView, ProjectionHasReversedDepthWithTheNearPlaneAtOne) {
  const View view = makeView(Body{}, Camera{.altitude = 2e4}, 1000, 500);
  const glm::vec4 atNear = view.projection * glm::vec4(0, 0, -float(view.near), 1);
  const glm::vec4 far = view.projection * glm::vec4(0, 0, -1e9f, 1);
  EXPECT_NEAR(atNear.z / atNear.w, 1.0, 1e-6);
  EXPECT_NEAR(far.z / far.w, 0.0, 1e-6);
  EXPECT_NEAR(view.projection[1][1] / view.projection[0][0], 2.0, 1e-6) << "aspect ratio 2";
}

}  // namespace
}  // namespace strata
