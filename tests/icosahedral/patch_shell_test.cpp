// The exact bounds of a patch's shell (plugins/geometry-icosahedral/patch_shell.hpp) against brute force:
// many points of the shell, each tested on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "patch_shell.hpp"

namespace strata::icosahedral {
namespace {

constexpr double kEarth = 6371000.0;

glm::dvec3 at(double lonDeg, double latDeg) {
  const double lon = glm::radians(lonDeg), lat = glm::radians(latDeg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// A point of the spherical triangle from barycentric weights.
glm::dvec3 inside(const SphericalTriangle& t, double u, double v) {
  return glm::normalize(t[0] * (1.0 - u - v) + t[1] * u + t[2] * v);
}

// Whether the segment from the eye to the point passes through the sphere of `radius`.
bool occluded(const glm::dvec3& eye, const glm::dvec3& point, double radius) {
  const glm::dvec3 d = point - eye;
  const double t = std::clamp(-glm::dot(eye, d) / glm::dot(d, d), 0.0, 1.0);
  return glm::length(eye + t * d) < radius;
}

const SphericalTriangle kTriangle{at(10, 10), at(30, 12), at(18, 35)};

TEST(PatchShell, TheSupportFunctionIsTheLargestDotOverTheTriangle) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> any(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 direction(any(random), any(random), any(random));
    double sampled = -2.0;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; i + j <= 60; ++j)
        sampled = std::max(sampled, glm::dot(direction, inside(kTriangle, i / 60.0, j / 60.0)));
    const double exact = largestDot(kTriangle, direction);
    EXPECT_GE(exact, sampled - 1e-12);                          // never below a point of the triangle
    EXPECT_LE(exact, sampled + 1e-3 * glm::length(direction));  // and the grid gets close to it
  }
}

TEST(PatchShell, ADirectionInsideIsItsOwnSupport) {
  const glm::dvec3 centre = inside(kTriangle, 1.0 / 3.0, 1.0 / 3.0) * 2.0;
  EXPECT_DOUBLE_EQ(largestDot(kTriangle, centre), 2.0);
  EXPECT_TRUE(holds(kTriangle, glm::normalize(centre)));
  EXPECT_FALSE(holds(kTriangle, -glm::normalize(centre)));
}

// A point's face-on distance: its distance over the square root of its cosine to the eye (at least
// kGrazingCosine).
double faceOnDistance(const glm::dvec3& unit, double radius, const glm::dvec3& eye) {
  const glm::dvec3 toEye = eye - radius * unit;
  const double distance = glm::length(toEye);
  return distance / std::sqrt(std::clamp(glm::dot(unit, toEye) / distance, kGrazingCosine, 1.0));
}

// Straight above a point inside the patch the bound is the altitude, a metre over an Earth-sized sphere
// without digits lost to R^2 - d^2. From anywhere it lies between the nearest point's distance and the
// least face-on distance of the patch's points, found by sampling them (every 1/64 of the way across the
// octant: the sampled nearest distance may lie up to about 0.02 above the true one).
TEST(PatchShell, TheLeastFaceOnDistanceBoundsEveryPointOfThePatch) {
  const SphericalTriangle octant{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
  EXPECT_NEAR(leastFaceOnDistance({octant, kEarth, kEarth}, glm::normalize(glm::dvec3(1, 1, 1)) * (kEarth + 1.0)), 1.0,
              1e-6);
  for (const glm::dvec3& eye : {glm::dvec3(-1, 1, 1) * 2.0, glm::dvec3(3, -1, 0.5), glm::dvec3(0.2, 0.3, 1.05)}) {
    double nearest = 1e300, leastFaceOn = 1e300;
    for (double a = 0.0; a <= 1.0; a += 1.0 / 64.0)
      for (double b = 0.0; a + b <= 1.0; b += 1.0 / 64.0) {
        const glm::dvec3 unit = inside(octant, a, b);
        nearest = std::min(nearest, glm::length(eye - unit));
        leastFaceOn = std::min(leastFaceOn, faceOnDistance(unit, 1.0, eye));
      }
    const double bound = leastFaceOnDistance({octant, 1.0, 1.0}, eye);
    EXPECT_GE(bound, nearest - 0.02) << "eye " << eye.x << ", " << eye.y << ", " << eye.z;
    EXPECT_LE(bound, leastFaceOn) << "eye " << eye.x << ", " << eye.y << ", " << eye.z;
  }
}

// 300 km beyond a 1000 m high eye lies past the sphere's horizon (113 km) but within sight of an
// 8848 m summit (113 km + 336 km): its shell must stay, and a shell of bare sphere there must go.
TEST(PatchShell, AMountainBehindTheSpheresHorizonStaysAboveIt) {
  const glm::dvec3 eye = at(0, 0) * (kEarth + 1000.0);
  const double ahead = glm::degrees(300e3 / kEarth), side = glm::degrees(1e3 / kEarth);
  const SphericalTriangle far{at(ahead, -side), at(ahead + side, 0), at(ahead, side)};
  EXPECT_FALSE(belowHorizon({far, kEarth, kEarth + 8848.0}, eye, kEarth));
  EXPECT_TRUE(belowHorizon({far, kEarth, kEarth}, eye, kEarth));
}

// Whatever belowHorizon or outsidePlane rules out, no point of the shell contradicts.
TEST(PatchShell, WhatIsRuledOutHasNoPointThatShows) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> lon(-180.0, 180.0), lat(-60.0, 60.0), height(0.0, 9000.0), any(-1.0, 1.0);
  int hidden = 0, outside = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double lo = lon(random), la = lat(random), size = 0.5 + 20.0 * (any(random) + 1.0);
    const SphericalTriangle t{at(lo, la), at(lo + size, la), at(lo + 0.5 * size, la + size)};
    const PatchShell shell{t, kEarth, kEarth + 8848.0};
    const glm::dvec3 eye =
        at(lon(random), lat(random)) * (kEarth + std::pow(10.0, 2.0 + 5.0 * (any(random) + 1.0) / 2.0));
    const glm::dvec3 normal(any(random), any(random), any(random));
    const double offset = -glm::dot(normal, at(lon(random), lat(random)) * kEarth);
    const bool belowIt = belowHorizon(shell, eye, kEarth), outsideIt = outsidePlane(shell, normal, offset);
    hidden += int(belowIt);
    outside += int(outsideIt);
    for (int i = 0; i <= 12; ++i)
      for (int j = 0; i + j <= 12; ++j) {
        const glm::dvec3 point = inside(t, i / 12.0, j / 12.0) * (kEarth + height(random));
        if (belowIt) {
          EXPECT_TRUE(occluded(eye, point, kEarth)) << trial;
        }
        if (outsideIt) {
          EXPECT_LT(glm::dot(normal, point) + offset, 0.0) << trial;
        }
      }
  }
  EXPECT_GT(hidden, 40);  // the trials rule out enough to mean something
  EXPECT_GT(outside, 40);
}

}  // namespace
}  // namespace strata::icosahedral
