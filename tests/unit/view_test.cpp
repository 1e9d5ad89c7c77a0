// makeView turns a user's camera into the eye position and axes, in double precision; cameraAhead extrapolates a
// moving camera for the prefetch.
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

glm::dvec3 eyeOf(const Body& body, const Camera& camera) { return makeView(body, camera, 64, 64).eye; }

// The eye goes on in a straight line, a chord, not along the surface: the paper's linear extrapolation. Across the
// antimeridian the longitude wraps; how the view looks stays as it is.
TEST(CameraAhead, TheEyeGoesOnInAStraightLine) {
  const Body mars{"Mars", 3389500.0};
  const Camera before{.lon = 179.99, .lat = -4.6, .altitude = 2000.0, .heading = 80.0, .tilt = 60.0};
  Camera now = before;
  now.lon = -179.995, now.altitude = 1900.0;
  const Camera ahead = cameraAhead(mars, before, now, 15.0);
  const glm::dvec3 expected = eyeOf(mars, now) + 15.0 * (eyeOf(mars, now) - eyeOf(mars, before));
  EXPECT_LT(glm::length(eyeOf(mars, ahead) - expected), 1e-6);  // m, of a 3.4e6 m position rebuilt by trigonometry
  EXPECT_NEAR(ahead.lon, -179.77, 1e-3);                        // 0.015 degrees a frame, 15 frames on
  EXPECT_EQ(ahead.heading, now.heading);
  EXPECT_EQ(ahead.tilt, now.tilt);
  EXPECT_EQ(ahead.fov, now.fov);
}

TEST(CameraAhead, AStillCameraStaysAndADescentStaysAboveTheGround) {
  const Body mars{"Mars", 3389500.0};
  const Camera now{.lon = 137.4, .lat = -4.6, .altitude = 100.0};
  EXPECT_LT(glm::length(eyeOf(mars, cameraAhead(mars, now, now, 15.0)) - eyeOf(mars, now)), 1e-6);
  Camera before = now;
  before.altitude = 150.0;  // 50 m a frame down: 15 frames on would be 650 m below the ground
  EXPECT_NEAR(cameraAhead(mars, before, now, 15.0).altitude, 10.0, 1e-6);
}

}  // namespace
}  // namespace strata
