// The procedural planet's height bounds over caps (planet_bounds.hpp): every sample a cap holds, at every
// footprint up to the cap's diameter, lies within them, anywhere on the body and at every size of cap; and
// they are narrow where the cap is small, which is what lets geometry measure a patch on its own terrain.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "planet_bounds.hpp"
#include "simplex_noise.hpp"

namespace strata::procedural {
namespace {

constexpr double kMarsRadius = 3396190.0;

glm::dvec3 directionOf(double lonDegrees, double latDegrees) {
  const double lon = glm::radians(lonDegrees), lat = glm::radians(latDegrees);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// A direction within `angle` of `centre`, uniform over the cap's area.
glm::dvec3 pointInCap(const glm::dvec3& centre, double angle, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cosAngle = 1.0 - unit(random) * (1.0 - std::cos(angle)), turn = 2.0 * std::numbers::pi * unit(random);
  const glm::dvec3 east =
      glm::normalize(glm::cross(std::abs(centre.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0), centre));
  const glm::dvec3 north = glm::cross(centre, east);
  const double sinAngle = std::sqrt(std::max(0.0, 1.0 - cosAngle * cosAngle));
  return glm::normalize(centre * cosAngle + (east * std::cos(turn) + north * std::sin(turn)) * sinAngle);
}

struct Place {
  double lon, lat;  // deg
};
// Gale crater's place, the antimeridian, both poles and the origin.
const Place kPlaces[] = {{137.4, -4.6}, {179.999, 10.0}, {-45.0, 89.95}, {60.0, -89.99}, {0.0, 0.0}};

TEST(PlanetBounds, HoldEverySampleOfTheCapAtEveryFootprintUpToItsDiameter) {
  const PlanetModel planet({}, kMarsRadius);
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int samples = 0;
  for (const Place& place : kPlaces)
    for (double metres = 0.5; metres < 2e7; metres *= 4.0) {  // cap radii from 50 cm to the whole body
      const double angle = std::min(metres / kMarsRadius, std::numbers::pi);
      const glm::dvec3 centre = directionOf(place.lon, place.lat);
      const HeightBounds bounds = heightsWithin(planet, centre, angle);
      for (int i = 0; i < 300; ++i, ++samples) {
        const double footprint = i % 3 == 0 ? 0.0 : unit(random) * 2.0 * angle * kMarsRadius;
        const double height = planet.height(pointInCap(centre, angle, random), footprint);
        ASSERT_GE(height, bounds.least) << "cap of " << metres << " m at " << place.lon << ", " << place.lat;
        ASSERT_LE(height, bounds.greatest) << "cap of " << metres << " m at " << place.lon << ", " << place.lat;
      }
    }
  EXPECT_GT(samples, 10000);
}

// The bounds widen with the cap at most as the noise's slope bound lets twelve octaves change, 0.29 m per
// metre each way at the defaults, plus the float slack of 12 cm each way: over a cap 2 m in radius they span
// under 2 m, over 20 km a quarter of the planet's 24 km range, and over the whole body they are that range.
TEST(PlanetBounds, NarrowWithTheCap) {
  const PlanetModel planet({}, kMarsRadius);
  const double amplitude = planet.parameters().amplitude;
  for (const Place& place : kPlaces) {
    const glm::dvec3 centre = directionOf(place.lon, place.lat);
    for (const double metres : {2.0, 200.0, 20e3}) {
      const HeightBounds bounds = heightsWithin(planet, centre, metres / kMarsRadius);
      EXPECT_LT(bounds.greatest - bounds.least, 0.6 * metres + 0.25)
          << metres << " m at " << place.lon << ", " << place.lat;
      EXPECT_LE(bounds.least, planet.height(centre));
      EXPECT_GE(bounds.greatest, planet.height(centre));
    }
    const HeightBounds whole = heightsWithin(planet, centre, std::numbers::pi);
    EXPECT_NEAR(whole.least, -kSimplexReach * amplitude, 1e-3 * amplitude);
    EXPECT_NEAR(whole.greatest, kSimplexReach * amplitude, 1e-3 * amplitude);
  }
}

}  // namespace
}  // namespace strata::procedural
