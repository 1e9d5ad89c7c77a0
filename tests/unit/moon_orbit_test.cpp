// The Moon's place from the Almanac's low-precision series against published positions, and its axes.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <strata/moon_orbit.hpp>
#include <strata/sun.hpp>

namespace strata {
namespace {

DayNumber at(const char* iso) { return *parseIsoDate(iso); }

// The angle between two directions, deg.
double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

// [Meeus 1998, example 47.a], from the full ELP-2000/82 theory: 1992 April 12 at 0h TD, the Moon at ecliptic
// longitude 133.162655, latitude -3.229126, 368,409.7 km from the Earth's centre, declination 13.768368. The
// series promise 0.3 degrees in longitude, 0.2 in latitude and 0.003 in parallax (0.3 per cent in distance);
// TD and UT differ by a minute, in which the Moon moves 0.01 degrees.
TEST(MoonPosition, MeetsMeeusExample47a) {
  const MoonPosition moon = moonPosition(at("1992-04-12"));
  EXPECT_NEAR(moon.lon, 133.162655, 0.3);
  EXPECT_NEAR(moon.lat, -3.229126, 0.2);
  EXPECT_NEAR(moon.distance, 368409.7e3, 368409.7e3 * 0.003);
  const glm::dvec3 centre = moonPlacement(at("1992-04-12")).centre;
  EXPECT_NEAR(glm::degrees(std::asin(centre.z / glm::length(centre))), 13.768368, 0.3);
  EXPECT_NEAR(glm::length(centre), moon.distance, 1e-3);
}

// At the greatest eclipse of 2024 April 8 (18:17 UT, gamma 0.3431: the shadow's axis passed 0.34 Earth radii from
// the Earth's centre [NASA eclipse bulletin]) the Moon stood 0.35 degrees from the Sun seen from the Earth's
// centre: the Moon's place and the Sun's (strata/sun.hpp) agree in the Earth's axes within the two series' error.
TEST(MoonPlacement, StandsBeforeTheSunAtTheTotalEclipseOf2024) {
  const DayNumber eclipse = at("2024-04-08T18:17Z");
  const glm::dvec3 sun = sunDirection(earthSubsolarPoint(eclipse));
  EXPECT_LT(degreesBetween(moonPlacement(eclipse).centre, sun), 0.35 + 0.4);
}

// At the greatest total eclipse of the Moon of 2022 November 8 (10:59 UT, gamma 0.2570 [NASA eclipse bulletin])
// it stood 0.25 degrees from the point opposite the Sun.
TEST(MoonPlacement, StandsOppositeTheSunAtTheLunarEclipseOf2022) {
  const DayNumber eclipse = at("2022-11-08T10:59Z");
  const glm::dvec3 sun = sunDirection(earthSubsolarPoint(eclipse));
  EXPECT_LT(degreesBetween(moonPlacement(eclipse).centre, -sun), 0.25 + 0.4);
}

// The Moon's axes are orthonormal and right-handed, its x toward the Earth's centre. Its z is the ecliptic's
// pole made perpendicular to x, which the orbit's tilt keeps within 5.1 degrees of the ecliptic: z lies within
// as much of that pole, 23.44 degrees from the Earth's.
TEST(MoonPlacement, ItsNearSideFacesTheEarth) {
  const BodyPlacement moon = moonPlacement(at("2024-03-20T18:00Z"));
  EXPECT_NEAR(glm::dot(moon.axes[0], -glm::normalize(moon.centre)), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(moon.axes[1]), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(moon.axes[0], moon.axes[2]), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(moon.axes[0], moon.axes[1]), moon.axes[2]), 1.0, 1e-12);
  EXPECT_NEAR(degreesBetween(moon.axes[2], glm::dvec3(0.0, 0.0, 1.0)), 23.44, 5.2);
}

}  // namespace
}  // namespace strata
