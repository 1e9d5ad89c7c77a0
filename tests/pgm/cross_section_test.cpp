// The 2D cross section of the PGM pass (plugins/geometry-pgm/cross_section.hpp) against exact 3D
// ray-sphere intersections in double, with the corrections to [Mahsman 2010, §3.6] that the code makes: the
// blend of Eq. 3.11 turned the way its text reads, and the position of §3.6.5 (docs/references.md, Errata).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "cross_section.hpp"
#include "reference_spheres.hpp"

namespace strata::pgm {
namespace {

constexpr double kMars = 3396000.0;  // m
constexpr double kRightAngle = 0.5 * std::numbers::pi;
constexpr double kTurn = 2.0 * std::numbers::pi;

// A unit ray at angle omega from the unit nadir, turned by the azimuth about it.
glm::dvec3 rayAt(const glm::dvec3& nadir, double rayAngle, double azimuth) {
  const glm::dvec3 other = std::abs(nadir.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 across = glm::normalize(glm::cross(nadir, other));
  const glm::dvec3 side = std::cos(azimuth) * across + std::sin(azimuth) * glm::cross(nadir, across);
  return std::cos(rayAngle) * nadir + std::sin(rayAngle) * side;
}

glm::dvec3 randomUnit(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
}

// The distance along the ray to its first hit on the sphere of `radius` centred d along the nadir: the
// smaller root of t^2 - 2 d w t + (d - r)(d + r) = 0, w = ray . nadir, as product over the larger root so
// that an eye a millimetre up loses nothing.
double exactHitDistance(double distance, double radius, const glm::dvec3& ray, const glm::dvec3& nadir) {
  const double half = distance * glm::dot(ray, nadir), constant = (distance - radius) * (distance + radius);
  return constant / (half + std::sqrt(half * half - constant));
}

// The normal angle of that hit: the angle at the centre between the eye and the hit.
double exactNormalAngle(double distance, double radius, const glm::dvec3& ray, const glm::dvec3& nadir) {
  const double t = exactHitDistance(distance, radius, ray, nadir);
  return std::atan2(t * glm::length(glm::cross(nadir, ray)), distance - t * glm::dot(ray, nadir));
}

// The 3D check tolerates 1e-11 of the distance. The reference and castRay round the ray's sine and cosine
// differently, by an ulp or two, and the hit's sensitivity to them grows as 1 / sqrt(w^2 - delta) towards
// the tangent, where the two roots meet; the 90,000 uniform rays here come within about 1e-5 tau0 of it.
// Measured worst: 1.0e-13 for positions, 6.6e-13 for normals (as unit-vector differences), so 1e-11 keeps
// a margin of 15 while a wrong formula is off by order 1 (the printed t = a).
constexpr double kHitTolerance = 1e-11;

// Without a secondary sphere every hit lies where the ray meets the primary sphere: eyes from 1 m to
// 20,000 km above Mars, rays anywhere from the nadir to the tangent.
TEST(PgmCrossSection, PositionsAreTheExactHitsFromAMetreToTwentyThousandKilometres) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> logAltitude(0.0, std::log(2e7)), unit(0.0, 1.0);
  for (int eye = 0; eye < 300; ++eye) {
    const double distance = kMars + std::exp(logAltitude(random));
    const CrossSection view = crossSection(distance, kMars, 0.0, 0.9);
    for (int trial = 0; trial < 300; ++trial) {
      const glm::dvec3 nadir = randomUnit(random);
      const glm::dvec3 ray = rayAt(nadir, view.primaryTangent * unit(random), kTurn * unit(random));
      const SpherePoint point = castRay(view, ray, nadir);
      ASSERT_TRUE(point.hit);
      const glm::dvec3 exact = exactHitDistance(distance, kMars, ray, nadir) * ray;
      ASSERT_LE(glm::length(point.position - exact), kHitTolerance * glm::length(exact)) << distance - kMars;
      ASSERT_LE(glm::length(point.normal - glm::normalize(exact - distance * nadir)), kHitTolerance);
    }
  }
}

// [Mahsman 2010, §3.6.5] (docs/references.md, Errata): d = 3397 km, r = 3396 km, omega = 67.61 degrees. The
// hit is 2.6276 km away; the printed t = a sin(rho)/sin(chi) would put it at a = 1 km. The corrected law of
// sines, t = a cos(gamma/2)/cos(gamma/2 + omega), agrees.
TEST(PgmCrossSection, TheDigestsExampleHitIsNotAtTheAltitude) {
  const CrossSection view = crossSection(3397.0, 3396.0, 0.0, 0.9);
  const glm::dvec3 nadir(0, 0, -1);
  const double rayAngle = glm::radians(67.61);
  const SpherePoint point = castRay(view, rayAt(nadir, rayAngle, 0.3), nadir);
  ASSERT_TRUE(point.hit);
  const double distance = glm::length(point.position);
  EXPECT_NEAR(distance, 2.6276, 0.5e-4);
  EXPECT_GT(distance - view.altitude, 1.6);
  const double half = 0.5 * normalAngle(view, std::sin(rayAngle), std::cos(rayAngle));
  EXPECT_NEAR(view.altitude * std::cos(half) / std::cos(half + rayAngle), distance, 1e-12);
}

// The worst relative error of the normal angle over many rays from the nadir to the tangent, against the
// exact hit, for the stable form and for the naive asin(c u) - asin(u).
struct NormalAngleErrors {
  double stable = 0.0, naive = 0.0;
};

NormalAngleErrors normalAngleErrors(double altitude) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double distance = kMars + altitude, tangent = tangentAngle(distance, kMars);
  NormalAngleErrors worst;
  for (int trial = 0; trial < 20000; ++trial) {
    const glm::dvec3 nadir = randomUnit(random);
    const glm::dvec3 ray = rayAt(nadir, tangent * unit(random), kTurn * unit(random));
    const double sine = glm::length(glm::cross(nadir, ray)), cosine = glm::dot(ray, nadir);
    const double exact = exactNormalAngle(distance, kMars, ray, nadir);
    const double stable = frontNormalAngle((distance - kMars) / kMars, sine, cosine);
    const double naive = std::asin(distance / kMars * sine) - std::asin(sine);
    worst.stable = std::max(worst.stable, std::abs(stable - exact) / exact);
    worst.naive = std::max(worst.naive, std::abs(naive - exact) / exact);
  }
  return worst;
}

// Near the ground c = d/r is barely above 1: rounding c alone costs the naive form ulp(1)/eps of its
// angle, asin(c u) - asin(u) cancels as much again, and near the tangent asin(c u) nears its vertical
// slope. Measured worst relative errors over these 20,000 rays, stable / naive: 1 mm up 1.6e-15 / 1.3e-6,
// 1 m up 1.7e-15 / 1.1e-9 (1.3e-8 over another draw of 100,000, whose worst rays graze the tangent),
// 1 km up 1.7e-15 / 3.3e-12. So in double the naive form misses 1e-9 at 1 mm by three orders and sits at it
// at 1 m. The stable form is kept for the GPU pass above all: in float c = 1 + 2.9e-7 is 2.5 ulps above 1
// at 1 m and the naive angle of [Mahsman 2010, §3.6.4, Eq. 3.10] is mostly rounding, while eps = a/r and the
// stable form's terms keep float's full relative precision.
TEST(PgmCrossSection, TheNormalAngleStaysExactAMillimetreAboveTheGround) {
  for (double altitude : {1e-3, 1.0, 1e3}) {
    SCOPED_TRACE(altitude);
    EXPECT_LT(normalAngleErrors(altitude).stable, 1e-13);
  }
  EXPECT_GT(normalAngleErrors(1e-3).naive, 1e-7);
}

// The exit point, pi - asin(c sin(omega)) - omega (Eq. 3.4), is the larger root of the same quadratic.
TEST(PgmCrossSection, TheBackFacingAngleIsTheExit) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> logAltitude(std::log(1e3), std::log(2e7)), unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double distance = kMars + std::exp(logAltitude(random));
    const double rayAngle = tangentAngle(distance, kMars) * unit(random);
    const double half = distance * std::cos(rayAngle), constant = (distance - kMars) * (distance + kMars);
    const double exit = half + std::sqrt(half * half - constant);
    const double exact = std::atan2(exit * std::sin(rayAngle), distance - exit * std::cos(rayAngle));
    EXPECT_NEAR(backNormalAngle(distance, kMars, rayAngle), exact, 1e-9);
  }
}

// [Mahsman 2010, §3.6.4, Eq. 3.11] (docs/references.md, Errata): with zeta = 0.9 blending starts at b = 0.9 tau0
// (f = 0), the tangent is all secondary (f = 1) and 0.95 tau0 averages the two (f = 0.5), as the text says; the
// printed Eq. 3.11 gives 1 at b.
// At f = 1 the ray samples gamma0, the farthest terrain that can rise into view.
TEST(PgmCrossSection, TheBlendRunsFromTheStartToTheTangent) {
  const double distance = kMars + 100e3;
  const ReferenceSpheres spheres = referenceSpheres(distance, kMars, kMars + 21.2e3);
  const CrossSection view = crossSection(distance, spheres.primary, spheres.secondary, 0.9);
  const double tangent = view.primaryTangent;
  EXPECT_EQ(blendFactor(view, 0.0), 0.0);
  EXPECT_EQ(blendFactor(view, 0.5 * tangent), 0.0);
  EXPECT_EQ(blendFactor(view, 0.9 * tangent), 0.0);
  EXPECT_NEAR(blendFactor(view, 0.95 * tangent), 0.5, 1e-12);
  EXPECT_NEAR(blendFactor(view, tangent), 1.0, 1e-12);
  const double outermost = outermostNormalAngle(distance, kMars, kMars + 21.2e3);
  EXPECT_NEAR(secondaryNormalAngle(view, 1.0), outermost, 1e-12);
  EXPECT_NEAR(normalAngle(view, std::sin(tangent), std::cos(tangent)), outermost, 1e-7);
}

// From 1 m to 27,000 km up (the secondary sphere vanishes at 27,139 km), every ray from the nadir to the
// tangent hits, with finite values, a unit normal, a point on the primary sphere, and normal angles that
// grow with the ray angle up to gamma0. Above 387 km b exceeds tau_s, so there the unclamped asin of the
// secondary angle ([Mahsman 2010, §3.6.4]) would be NaN near f = 0.
TEST(PgmCrossSection, NoNaNFromTheNadirToTheTangent) {
  const double maximum = kMars + 21.2e3;
  for (double altitude : {1.0, 1e3, 100e3, 387e3, 390e3, 1e6, 5e6, 2e7, 2.7e7}) {
    SCOPED_TRACE(altitude);
    const double distance = kMars + altitude;
    const ReferenceSpheres spheres = referenceSpheres(distance, kMars, maximum);
    const CrossSection view = crossSection(distance, spheres.primary, spheres.secondary, 0.9);
    ASSERT_GT(view.secondaryRadius, 0.0);
    if (altitude >= 390e3) {
      EXPECT_GT(distance / view.secondaryRadius * std::sin(view.blendStart), 1.0);
    }
    const double outermost = outermostNormalAngle(distance, kMars, maximum);
    const glm::dvec3 nadir = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    double previous = 0.0;
    for (int step = 0; step <= 4000; ++step) {
      const double rayAngle = view.primaryTangent * std::min(step / 4000.0, 1.0 - 1e-12);
      const double gamma = normalAngle(view, std::sin(rayAngle), std::cos(rayAngle));
      ASSERT_TRUE(std::isfinite(gamma)) << rayAngle;
      ASSERT_GE(gamma, previous - 1e-12) << rayAngle;
      ASSERT_LE(gamma, outermost + 1e-7) << rayAngle;
      previous = gamma;
      const SpherePoint point = castRay(view, rayAt(nadir, rayAngle, 1.0), nadir);
      ASSERT_TRUE(point.hit) << rayAngle;
      ASSERT_NEAR(glm::length(point.normal), 1.0, 1e-14);
      const glm::dvec3 fromCentre = point.position - distance * nadir;
      ASSERT_LE(glm::length(fromCentre - kMars * point.normal), 1e-9 * distance) << rayAngle;
    }
  }
}

// Beyond the tangent, or more than 90 degrees from the nadir (which would alias onto omega < 90 degrees),
// the ray misses, and its point is that of the ray of its plane at the tangent: gamma0 with a secondary
// sphere, the horizon without one.
TEST(PgmCrossSection, RaysBeyondTheTangentOrAwayFromThePlanetMissAndGiveTheHorizon) {
  for (double altitude : {1e-3, 1.0, 1e4, 2e7}) {
    const double distance = kMars + altitude;
    const ReferenceSpheres spheres = referenceSpheres(distance, kMars, kMars + 21.2e3);
    const CrossSection view = crossSection(distance, spheres.primary, spheres.secondary, 0.9);
    const glm::dvec3 nadir(0, 0, -1);
    const double tangent = view.primaryTangent;
    for (double rayAngle : {tangent * (1.0 + 1e-9), 0.5 * (tangent + kRightAngle), kRightAngle, 2.0,
                            std::numbers::pi - 0.3, std::numbers::pi}) {
      SCOPED_TRACE(rayAngle);
      const SpherePoint point = castRay(view, rayAt(nadir, rayAngle, 0.7), nadir);
      const SpherePoint horizon = castRay(view, rayAt(nadir, tangent, 0.7), nadir);
      EXPECT_FALSE(point.hit);
      if (rayAngle < std::numbers::pi) {  // straight up the plane is any: the azimuth is not 0.7
        EXPECT_LT(glm::length(point.normal - horizon.normal), 1e-15);
        EXPECT_LT(glm::length(point.position - horizon.position), 1e-15 * glm::length(horizon.position));
      }
      const double gamma = std::acos(-glm::dot(point.normal, nadir));
      EXPECT_NEAR(gamma,
                  view.secondaryRadius > 0.0 ? 0.5 * std::numbers::pi - view.secondaryTangent
                                             : 0.5 * std::numbers::pi - tangent,
                  1e-7);
    }
    EXPECT_TRUE(castRay(view, rayAt(nadir, tangent * (1.0 - 1e-9), 0.7), nadir).hit);
    EXPECT_TRUE(misses(view.altitude / kMars, std::sin(tangent * (1.0 + 1e-9)), std::cos(tangent * (1.0 + 1e-9))));
  }
}

// Straight down the cross-section plane is undefined: the ray meets the ground at the nadir point, gamma = 0.
TEST(PgmCrossSection, TheNadirRayHitsTheNadirPoint) {
  const double distance = kMars + 2.0;
  const CrossSection view = crossSection(distance, kMars, 0.0, 0.9);
  const glm::dvec3 nadir = glm::normalize(glm::dvec3(1, 2, -3));
  for (const glm::dvec3& ray : {nadir, rayAt(nadir, 1e-17, 0.0), rayAt(nadir, 1e-12, 0.0)}) {
    const SpherePoint point = castRay(view, ray, nadir);
    ASSERT_TRUE(point.hit);
    EXPECT_LT(glm::length(point.normal + nadir), 1e-15);
    EXPECT_LT(glm::length(point.position - 2.0 * nadir), 1e-11);
  }
}

}  // namespace
}  // namespace strata::pgm
