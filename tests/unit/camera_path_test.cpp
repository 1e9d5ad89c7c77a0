// CameraPath in double precision: keyframes are met exactly, the spline has no jump in position or velocity
// at keyframes, altitude moves in log space, headings turn the shorter way, and tracks stay on great circles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/glm.hpp>

#include <strata/host/camera_path.hpp>

namespace strata {
namespace {

glm::dvec3 groundPoint(const Camera& camera) {
  constexpr double degree = std::numbers::pi / 180.0;
  return unitNormal(camera.lon * degree, camera.lat * degree);
}

// The angle (deg) between two headings, the shorter way round.
double headingDifference(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

Camera camera(double lon, double lat, double altitude, double heading = 0.0, double tilt = 0.0) {
  return Camera{lon, lat, altitude, heading, tilt, 45.0};
}

// A fly-in with a turn: from a wide view of the Earth down to a tilted view of a mountain and along a valley.
CameraPath flyIn() {
  return CameraPath::throughKeyframes({{0.0, camera(0.0, 20.0, 2.0e7)},
                                       {4.0, camera(8.0, 40.0, 3.0e5, 20.0, 30.0)},
                                       {10.0, camera(10.0, 46.0, 5000.0, 30.0, 70.0)},
                                       {12.0, camera(10.2, 46.1, 2000.0, 60.0, 80.0)}});
}

TEST(CameraPathTest, MeetsEachKeyframeExactlyAtItsTime) {
  const std::vector<CameraKeyframe> keyframes{{0.0, camera(0.0, 20.0, 2.0e7)},
                                              {4.0, camera(8.0, 40.0, 3.0e5, 20.0, 30.0)},
                                              {10.0, camera(10.0, 46.0, 5000.0, 30.0, 70.0)},
                                              {12.0, camera(10.2, 46.1, 2000.0, 60.0, 80.0)}};
  const CameraPath path = flyIn();
  EXPECT_EQ(path.start(), 0.0);
  EXPECT_EQ(path.end(), 12.0);
  for (const auto& keyframe : keyframes) {
    const Camera at = path.at(keyframe.time);
    EXPECT_NEAR(at.lon, keyframe.camera.lon, 1e-12) << "t = " << keyframe.time;
    EXPECT_NEAR(at.lat, keyframe.camera.lat, 1e-12);
    EXPECT_NEAR(at.altitude / keyframe.camera.altitude, 1.0, 1e-13);
    EXPECT_NEAR(headingDifference(at.heading, keyframe.camera.heading), 0.0, 1e-12);
    EXPECT_NEAR(at.tilt, keyframe.camera.tilt, 1e-12);
    EXPECT_NEAR(at.fov, keyframe.camera.fov, 1e-12);
  }
}

TEST(CameraPathTest, HoldsTheEndsOutsideItsTimeAndStepsByFraction) {
  const CameraPath path = flyIn();
  EXPECT_NEAR(path.at(-5.0).altitude, 2.0e7, 1e-6);
  EXPECT_NEAR(path.at(99.0).altitude, 2000.0, 1e-9);
  const Camera half = path.atFraction(0.5), sixSeconds = path.at(6.0);
  EXPECT_EQ(half.lon, sixSeconds.lon);
  EXPECT_EQ(half.altitude, sixSeconds.altitude);
}

// The relative change of the track's velocity across `time`, from one-sided finite differences over `step`.
double velocityJump(const CameraPath& path, double time, double step) {
  const glm::dvec3 before = groundPoint(path.at(time - step)), at = groundPoint(path.at(time));
  const glm::dvec3 after = groundPoint(path.at(time + step));
  const glm::dvec3 velocityBefore = (at - before) / step, velocityAfter = (after - at) / step;
  return glm::length(velocityAfter - velocityBefore) / glm::length(velocityAfter);
}

// The point below the camera, its altitude and heading have no jump in value nor in velocity at a keyframe:
// one-sided finite differences agree to within what the curvature gives over the step, and ten times closer
// over a step ten times shorter (a kink would not shrink).
TEST(CameraPathTest, IsContinuousWithContinuousVelocityAcrossKeyframes) {
  const CameraPath path = flyIn();
  constexpr double step = 1e-4;  // s
  for (const double knot : {4.0, 10.0}) {
    const double jump = velocityJump(path, knot, step), finer = velocityJump(path, knot, step / 10.0);
    std::printf("t = %g s: relative change of the track's velocity over 2 x %g s: %.2e, over 2 x %g s: %.2e\n", knot,
                step, jump, step / 10.0, finer);
    EXPECT_LT(jump, 1e-3) << "t = " << knot;
    EXPECT_NEAR(finer / jump, 0.1, 0.01) << "t = " << knot;
    const Camera before = path.at(knot - step), at = path.at(knot), after = path.at(knot + step);
    const double logRateBefore = std::log(at.altitude / before.altitude) / step;
    const double logRateAfter = std::log(after.altitude / at.altitude) / step;
    EXPECT_NEAR(logRateBefore, logRateAfter, 1e-3 * std::abs(logRateAfter) + 1e-9) << "t = " << knot;
    const double turnBefore = std::remainder(at.heading - before.heading, 360.0) / step;
    const double turnAfter = std::remainder(after.heading - at.heading, 360.0) / step;
    EXPECT_NEAR(turnBefore, turnAfter, 1e-2) << "t = " << knot;
  }
}

// From 100,000 km to 1 m, the altitude moves in log space: halfway in time it is the geometric mean, and
// its relative rate (dh/dt)/h is the same high up as near the ground.
TEST(CameraPathTest, InterpolatesAltitudeInLogSpace) {
  const CameraPath path = CameraPath::throughKeyframes({{0.0, camera(0.0, 0.0, 1.0e8)}, {10.0, camera(0.0, 0.0, 1.0)}});
  EXPECT_NEAR(path.at(5.0).altitude / 1.0e4, 1.0, 1e-12);
  const auto relativeRate = [&](double time) {
    constexpr double step = 1e-5;
    return std::log(path.at(time + step).altitude / path.at(time - step).altitude) / (2.0 * step);
  };
  const double high = relativeRate(2.5), low = relativeRate(7.5);
  EXPECT_GT(path.at(2.5).altitude / path.at(7.5).altitude, 1e5);
  EXPECT_NEAR(high / low, 1.0, 1e-6);
}

// Monotone cubics: between two keyframes at 5 km the altitude stays at 5 km, never dipping below.
TEST(CameraPathTest, AltitudeNeverOvershootsItsKeyframes) {
  const CameraPath path = CameraPath::throughKeyframes({{0.0, camera(0.0, 0.0, 2.0e7)},
                                                        {5.0, camera(1.0, 0.0, 5000.0)},
                                                        {6.0, camera(1.1, 0.0, 5000.0)},
                                                        {9.0, camera(2.0, 0.0, 2.0e7)}});
  double lowest = 1e300;
  for (int i = 0; i <= 9000; ++i) lowest = std::min(lowest, path.at(i * 1e-3).altitude);
  EXPECT_GE(lowest, 5000.0 * (1.0 - 1e-12));
}

// 350 to 10 degrees turns through north, not back through south.
TEST(CameraPathTest, HeadingTurnsTheShorterWayRound) {
  const CameraPath path =
      CameraPath::throughKeyframes({{0.0, camera(0.0, 0.0, 1e6, 350.0)}, {1.0, camera(0.0, 0.0, 1e6, 10.0)}});
  EXPECT_NEAR(headingDifference(path.at(0.5).heading, 0.0), 0.0, 1e-12);
  for (int i = 0; i <= 100; ++i) {
    const double heading = path.at(i / 100.0).heading;
    EXPECT_TRUE(heading >= 350.0 || heading <= 10.0) << heading;
    EXPECT_GE(heading, 0.0);
    EXPECT_LT(heading, 360.0);
  }
}

// The unit normal of the great circle through two ground points (lon, lat in deg).
glm::dvec3 greatCircleNormal(const Camera& a, const Camera& b) {
  return glm::normalize(glm::cross(groundPoint(a), groundPoint(b)));
}

TEST(CameraPathTest, KeyframesOnOneGreatCircleKeepTheTrackOnIt) {
  // Three points of the great circle through (-40, -10) and (60, 50), the middle one found by slerp.
  const Camera a = camera(-40.0, -10.0, 1e7), c = camera(60.0, 50.0, 1e4);
  const glm::dvec3 normal = greatCircleNormal(a, c);
  const glm::dvec3 middle = glm::normalize(groundPoint(a) + groundPoint(c));
  const Camera b = camera(std::atan2(middle.y, middle.x) * 180.0 / std::numbers::pi,
                          std::asin(middle.z) * 180.0 / std::numbers::pi, 1e5);
  const CameraPath path = CameraPath::throughKeyframes({{0.0, a}, {3.0, b}, {4.0, c}});
  double farthest = 0.0;
  for (int i = 0; i <= 4000; ++i)
    farthest = std::max(farthest, std::abs(glm::dot(groundPoint(path.at(i * 1e-3)), normal)));
  std::printf("farthest from the great circle: %.2e rad\n", farthest);
  EXPECT_LT(farthest, 1e-14);  // rad: 64 nm on the Earth
}

TEST(CameraPathTest, RefusesTooFewLateOrAntipodalKeyframes) {
  EXPECT_THROW(CameraPath::throughKeyframes({{0.0, camera(0.0, 0.0, 1e6)}}), std::invalid_argument);
  EXPECT_THROW(CameraPath::throughKeyframes({{1.0, camera(0.0, 0.0, 1e6)}, {1.0, camera(1.0, 0.0, 1e6)}}),
               std::invalid_argument);
  EXPECT_THROW(CameraPath::throughKeyframes({{0.0, camera(0.0, 10.0, 1e6)}, {1.0, camera(180.0, -10.0, 1e6)}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace strata
