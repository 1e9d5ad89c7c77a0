// The sampling camera (plugins/geometry-pgm/sampling_camera.hpp) against exact 3D ray-sphere tests in
// double, for views of Mars from 2 m to 20,000 km up ([Mahsman 2010, §3.5]).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "sampling_camera.hpp"

namespace strata::pgm {
namespace {

constexpr double kMars = 3396000.0;  // m

// A view from latitude, longitude and altitude, its forward turned by the tilt from the nadir towards the
// heading (from north through east) and rolled about itself; planet-fixed axes as Strata's, +z north and
// +x at longitude 0.
struct Pose {
  double latitude, longitude, altitude, tilt, heading, roll = 0.0;  // radians, m
};

// A frustum of vertical field of view fovY and width over height `aspect`, its centre shifted by `shift`
// of its half-height up, on the near plane at 0.5.
ViewCamera viewAt(const Pose& pose, double fovY, double aspect, double shift = 0.0) {
  const double cosLat = std::cos(pose.latitude);
  const glm::dvec3 up(cosLat * std::cos(pose.longitude), cosLat * std::sin(pose.longitude), std::sin(pose.latitude));
  const glm::dvec3 east(-std::sin(pose.longitude), std::cos(pose.longitude), 0.0), north = glm::cross(up, east);
  const glm::dvec3 level = std::cos(pose.heading) * north + std::sin(pose.heading) * east;
  const glm::dvec3 forward = -std::cos(pose.tilt) * up + std::sin(pose.tilt) * level;
  const glm::dvec3 above = std::sin(pose.tilt) * up + std::cos(pose.tilt) * level;
  const glm::dvec3 side = glm::cross(forward, above);
  const glm::dvec3 right = std::cos(pose.roll) * side + std::sin(pose.roll) * above;
  const double near = 0.5, top = near * std::tan(0.5 * fovY);
  return {.eye = (kMars + pose.altitude) * up,
          .planetToEye = glm::transpose(glm::dmat3(right, glm::cross(-forward, right), -forward)),
          .left = -aspect * top,
          .right = aspect * top,
          .bottom = (shift - 1.0) * top,
          .top = (shift + 1.0) * top,
          .near = near};
}

// Whether a unit planet-fixed ray from the eye meets Mars: towards the centre, and d sin(omega) <= r.
bool hitsMars(const glm::dvec3& eye, const glm::dvec3& ray) {
  const glm::dvec3 nadir = -glm::normalize(eye);
  return glm::dot(ray, nadir) > 0.0 && glm::length(eye) * glm::length(glm::cross(ray, nadir)) <= kMars;
}

// How far a planet-fixed ray lands outside the sampling frustum on its near plane, as a fraction of the
// frustum's larger side; at most 0 inside, infinite behind the eye.
double overshoot(const SamplingCamera& camera, const glm::dvec3& ray) {
  const glm::dvec3 sampled = camera.planetToSampling * ray;
  if (sampled.z >= 0.0) return std::numeric_limits<double>::infinity();
  const double x = -camera.near * sampled.x / sampled.z, y = -camera.near * sampled.y / sampled.z;
  const double beyond = std::max({camera.left - x, x - camera.right, camera.bottom - y, y - camera.top});
  return beyond / std::max(camera.right - camera.left, camera.top - camera.bottom);
}

// A unit ray through the point (x, y) of a view's near plane, planet-fixed.
glm::dvec3 viewRay(const ViewCamera& view, double x, double y) {
  return glm::transpose(view.planetToEye) * glm::normalize(glm::dvec3(x, y, -view.near));
}

// A random ray from the eye that hits Mars: up to the tangent angle from the nadir, any azimuth; a sixth
// of them graze it at the tangent angle, where the visible-sphere frustum's sides touch the sphere.
glm::dvec3 randomSphereRay(const glm::dvec3& eye, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const glm::dvec3 nadir = -glm::normalize(eye);
  const glm::dvec3 across = glm::normalize(glm::cross(nadir, glm::dvec3(0.3, 0.5, 0.7)));
  const double angle = std::asin(kMars / glm::length(eye)) * std::min(1.2 * unit(random), 1.0),
               azimuth = 2.0 * std::numbers::pi * unit(random);
  const glm::dvec3 side = std::cos(azimuth) * across + std::sin(azimuth) * glm::cross(nadir, across);
  return std::cos(angle) * nadir + std::sin(angle) * side;
}

// Rays that hit are covered up to rounding. The fitted rays lie on the frustum's edges, and a ray that
// turns by delta moves its near-plane point x = near tan(theta) by delta near (1 + tan^2 theta): relative
// to the side, by delta (near/side + side/near) at most. Taken back to planet-fixed space and out again,
// the fitted rays overshoot by at most 5.0e-12 of the side in the widest frusta (the VSF alone near the
// ground, 22,360 near distances wide at the altitude clamp) and 2.4e-14 in the narrowest, at worst
// 1.8e-15 (near/side + side/near) (measured over the 5,000 views of the last test); the rays that hit stay
// inside everywhere else. So a delta of 1e-14, some 50 ulps, is rounding with a margin of 5.7,
// while a lost sliver of the sphere overshoots by orders more.
double coverTolerance(const SamplingCamera& camera) {
  const double side = std::max(camera.right - camera.left, camera.top - camera.bottom);
  return 1e-14 * (camera.near / side + side / camera.near);
}

TEST(PgmSamplingCamera, EveryViewRayThatHitsIsCovered) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double latitudes[] = {0.0, 0.6, -1.1, glm::radians(89.9), glm::radians(-89.9)};
  for (int eye = 0; eye < 600; ++eye) {
    const Pose pose{.latitude = latitudes[eye % 5],
                    .longitude = 6.3 * unit(random),
                    .altitude = std::exp(std::log(2.0) + unit(random) * std::log(1e7)),
                    .tilt = glm::radians(90.0) * unit(random),
                    .heading = 6.3 * unit(random),
                    .roll = 0.6 * (unit(random) - 0.5)};
    const ViewCamera view =
        viewAt(pose, glm::radians(20.0 + 80.0 * unit(random)), 0.5 + 1.5 * unit(random), unit(random) - 0.5);
    const SamplingCamera camera = samplingCamera(view, kMars);
    for (int trial = 0; trial < 2000; ++trial) {
      const double across = trial % 4 == 0 ? std::round(unit(random)) : unit(random);
      const double upward = trial % 4 == 1 ? std::round(unit(random)) : unit(random);
      const glm::dvec3 ray =
          viewRay(view, view.left + (view.right - view.left) * across, view.bottom + (view.top - view.bottom) * upward);
      if (!hitsMars(view.eye, ray)) continue;
      ASSERT_LE(overshoot(camera, ray), coverTolerance(camera)) << pose.altitude << " " << pose.tilt;
    }
  }
}

// Nadir extension: rays between the nadir and the bottom of the view frustum, in the view's vertical plane
// (the eye's yz-plane, without roll) and towards any point of the bottom edge, are covered where they hit.
TEST(PgmSamplingCamera, RaysDownToTheNadirAreCovered) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int eye = 0; eye < 300; ++eye) {
    const Pose pose{.latitude = 1.5 * (unit(random) - 0.5),
                    .longitude = 6.3 * unit(random),
                    .altitude = std::exp(std::log(2.0) + unit(random) * std::log(1e7)),
                    .tilt = glm::radians(40.0 + 50.0 * unit(random)),
                    .heading = 6.3 * unit(random)};
    const ViewCamera view = viewAt(pose, glm::radians(20.0 + 40.0 * unit(random)), 0.5 + 1.5 * unit(random));
    const SamplingCamera camera = samplingCamera(view, kMars);
    const glm::dvec3 nadir = -glm::normalize(view.eye);
    if (camera.fit != SamplingFit::kVisibleSphereAlone) {
      EXPECT_EQ(camera.fit, SamplingFit::kExtendedToNadir);
    }
    for (int trial = 0; trial < 400; ++trial) {
      const double across = trial % 2 == 0 ? 0.0 : view.left + (view.right - view.left) * unit(random);
      const glm::dvec3 bottom = viewRay(view, across, view.bottom);
      const glm::dvec3 ray = glm::normalize(nadir + unit(random) * (bottom - nadir));
      if (hitsMars(view.eye, ray)) {
        ASSERT_LE(overshoot(camera, ray), coverTolerance(camera)) << pose.altitude;
      }
    }
    EXPECT_LE(overshoot(camera, nadir), coverTolerance(camera));
  }
}

// The fraction of the sampling frustum's rays that hit, over a 400 x 400 grid on its near plane.
double hitFraction(const SamplingCamera& camera, const glm::dvec3& eye) {
  int hits = 0;
  for (int row = 0; row < 400; ++row) {
    for (int column = 0; column < 400; ++column) {
      const double x = camera.left + (camera.right - camera.left) * (column + 0.5) / 400.0;
      const double y = camera.bottom + (camera.top - camera.bottom) * (row + 0.5) / 400.0;
      hits += hitsMars(eye, glm::transpose(camera.planetToSampling) * glm::normalize(glm::dvec3(x, y, -camera.near)));
    }
  }
  return hits / 160000.0;
}

// Aligned with the horizon, the sampling frustum wastes few rays near the ground: 1 km up, tilted 80
// degrees, 60 degrees of vertical field of view at 16:9. Measured: 99.64% of its rays hit; the misses are the sliver
// between the horizon and the VSF's top plane, which touches it only straight ahead.
TEST(PgmSamplingCamera, MostSamplingRaysHitNearTheGround) {
  const ViewCamera view =
      viewAt({.latitude = 0.3, .longitude = 1.0, .altitude = 1e3, .tilt = glm::radians(80.0), .heading = 0.7},
             glm::radians(60.0), 16.0 / 9.0);
  const SamplingCamera camera = samplingCamera(view, kMars);
  EXPECT_GE(hitFraction(camera, view.eye), 0.5);
}

// Every sphere ray of a random view, wherever it points, is covered when the camera falls back to the
// visible-sphere frustum or sees the whole disc.
void expectSphereCovered(const ViewCamera& view, const SamplingCamera& camera) {
  std::mt19937 random(17);
  for (int trial = 0; trial < 20000; ++trial) {
    ASSERT_LE(overshoot(camera, randomSphereRay(view.eye, random)), coverTolerance(camera));
  }
}

// Looking straight away from the planet the frusta do not meet: the VSF alone, which still holds the
// whole visible sphere, from 2 m to 20,000 km up.
TEST(PgmSamplingCamera, LookingAwayFallsBackToTheVisibleSphereFrustum) {
  for (double altitude : {2.0, 1e3, 1e6, 2e7}) {
    SCOPED_TRACE(altitude);
    const ViewCamera view =
        viewAt({.latitude = 0.4, .longitude = 2.0, .altitude = altitude, .tilt = std::numbers::pi, .heading = 0.3},
               glm::radians(60.0), 1.5);
    const SamplingCamera camera = samplingCamera(view, kMars);
    EXPECT_EQ(camera.fit, SamplingFit::kVisibleSphereAlone);
    expectSphereCovered(view, camera);
  }
}

// Straight down, with the forward exactly the nadir: the rotated eye frame falls back to eye space and,
// the view frustum being symmetric, the sampling camera is the viewing camera's orientation (Fig. 3.47).
TEST(PgmSamplingCamera, StraightDownKeepsTheScreenAxes) {
  for (double altitude : {2.0, 1e5, 2e7}) {
    SCOPED_TRACE(altitude);
    const ViewCamera view{.eye = glm::dvec3(0.0, 0.0, kMars + altitude),
                          .planetToEye = glm::dmat3(1.0),
                          .left = -0.4,
                          .right = 0.4,
                          .bottom = -0.3,
                          .top = 0.3,
                          .near = 0.5};
    const SamplingCamera camera = samplingCamera(view, kMars);
    EXPECT_NE(camera.fit, SamplingFit::kExtendedToNadir);
    for (int column = 0; column < 3; ++column) {
      EXPECT_LT(glm::length(camera.planetToSampling[column] - view.planetToEye[column]), 1e-15);
    }
    std::mt19937 random(19);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
      const glm::dvec3 ray = viewRay(view, -0.4 + 0.8 * unit(random), -0.3 + 0.6 * unit(random));
      if (hitsMars(view.eye, ray)) {
        ASSERT_LE(overshoot(camera, ray), coverTolerance(camera));
      }
    }
  }
}

// At the poles, down to the exact pole, the construction uses no geographic frame: straight down and
// towards the horizon alike.
TEST(PgmSamplingCamera, AtThePoles) {
  for (double latitude : {90.0, -90.0, 89.9, -89.9}) {
    for (double tilt : {0.0, 45.0, 88.0}) {
      SCOPED_TRACE(latitude + tilt / 1000.0);
      const ViewCamera view = viewAt({.latitude = glm::radians(latitude),
                                      .longitude = 0.0,
                                      .altitude = 10.0,
                                      .tilt = glm::radians(tilt),
                                      .heading = 1.0},
                                     glm::radians(50.0), 1.2);
      const SamplingCamera camera = samplingCamera(view, kMars);
      for (int row = 0; row <= 40; ++row) {
        for (int column = 0; column <= 40; ++column) {
          const glm::dvec3 ray = viewRay(view, view.left + (view.right - view.left) * column / 40.0,
                                         view.bottom + (view.top - view.bottom) * row / 40.0);
          if (hitsMars(view.eye, ray)) {
            ASSERT_LE(overshoot(camera, ray), coverTolerance(camera));
          }
        }
      }
    }
  }
}

// From 20,000 km with 30 degrees of field of view the whole disc (tau = 8.3 degrees) is in view: the VSF
// lies inside the view frustum, and every ray that hits is covered.
TEST(PgmSamplingCamera, TheWholeDiscFromTwentyThousandKilometres) {
  for (double tilt : {0.0, 3.0}) {
    const ViewCamera view =
        viewAt({.latitude = 0.2, .longitude = 0.5, .altitude = 2e7, .tilt = glm::radians(tilt), .heading = 2.0},
               glm::radians(30.0), 1.0);
    const SamplingCamera camera = samplingCamera(view, kMars);
    EXPECT_EQ(camera.fit, SamplingFit::kIntersection);
    expectSphereCovered(view, camera);
  }
}

// For any view, tilted anywhere from straight down to straight up and from 1 mm to 20,000 km up, the
// near-plane box is finite and not empty and every fitted ray points down -z in sampling space.
TEST(PgmSamplingCamera, TheFrustumIsFiniteAndEveryRayPointsAhead) {
  std::mt19937 random(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int eye = 0; eye < 5000; ++eye) {
    const Pose pose{.latitude = 3.2 * (unit(random) - 0.5),
                    .longitude = 6.3 * unit(random),
                    .altitude = std::exp(std::log(1e-3) + unit(random) * std::log(2e10)),
                    .tilt = std::numbers::pi * unit(random),
                    .heading = 6.3 * unit(random),
                    .roll = 6.3 * unit(random)};
    const ViewCamera view =
        viewAt(pose, glm::radians(10.0 + 140.0 * unit(random)), 0.3 + 3.0 * unit(random), 2.0 * (unit(random) - 0.5));
    const SamplingCamera camera = samplingCamera(view, kMars);
    ASSERT_TRUE(std::isfinite(camera.left) && std::isfinite(camera.right)) << pose.altitude;
    ASSERT_TRUE(std::isfinite(camera.bottom) && std::isfinite(camera.top)) << pose.altitude;
    ASSERT_LT(camera.left, camera.right);
    ASSERT_LT(camera.bottom, camera.top);
    ASSERT_GE(camera.rays.size(), 3u);
    for (const glm::dvec3& ray : camera.rays) {
      ASSERT_LT(ray.z, 0.0) << pose.altitude << " " << pose.tilt;
      ASSERT_LE(overshoot(camera, glm::transpose(camera.planetToSampling) * ray), coverTolerance(camera));
    }
  }
}

}  // namespace
}  // namespace strata::pgm
