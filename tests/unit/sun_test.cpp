// The Earth's subsolar point from the date against published almanac values, and the scene's sun.
#include <gtest/gtest.h>

#include <cmath>
#include <strata/sun.hpp>

namespace strata {
namespace {

// A tenth of a degree: ten times what the Almanac's low-precision formulas promise from 1950 to 2050
// [Almanac 2024, §C5].
constexpr double kDegrees = 0.1;

DayNumber at(const char* iso) { return *parseIsoDate(iso); }

// The equinoxes and solstices of 2024 (USNO, "Earth's Seasons", to the minute, UT): the Sun's declination is
// 0 at an equinox and the obliquity of the ecliptic (23.44 degrees) at a solstice.
TEST(EarthSubsolarPoint, LatitudeAtTheEquinoxesAndSolsticesOf2024) {
  EXPECT_NEAR(earthSubsolarPoint(at("2024-03-20T03:06Z")).lat, 0.0, kDegrees);
  EXPECT_NEAR(earthSubsolarPoint(at("2024-06-20T20:51Z")).lat, 23.44, kDegrees);
  EXPECT_NEAR(earthSubsolarPoint(at("2024-09-22T12:44Z")).lat, 0.0, kDegrees);
  EXPECT_NEAR(earthSubsolarPoint(at("2024-12-21T09:21Z")).lat, -23.44, kDegrees);
}

// JPL Horizons (DE441), the Sun seen from the Earth's centre at 2023-06-21 12:00 UT: declination 23.43572.
TEST(EarthSubsolarPoint, LatitudeAtTheJune2023SolsticeIsHorizons) {
  EXPECT_NEAR(earthSubsolarPoint(at("2023-06-21T12:00Z")).lat, 23.43572, kDegrees);
}

// At 12:00 UT the Sun stands over longitude -15 degrees an hour times the equation of time. Its yearly
// extremes as commonly published, +16 min 33 s about 3 November and -14 min 6 s about 11 February, move by a
// few seconds (0.03 degrees) from year to year: the subsolar point lies 4.14 degrees west and 3.53 east.
TEST(EarthSubsolarPoint, LongitudeAtNoonFollowsTheEquationOfTime) {
  EXPECT_NEAR(earthSubsolarPoint(at("2024-11-03T12:00Z")).lon, -4.14, kDegrees);
  EXPECT_NEAR(earthSubsolarPoint(at("2024-02-11T12:00Z")).lon, 3.53, kDegrees);
}

// The Earth turns once in a solar day: six hours later the Sun stands 90 degrees further west.
TEST(EarthSubsolarPoint, MovesWestAQuarterTurnInSixHours) {
  const SubsolarPoint noon = earthSubsolarPoint(at("2024-03-20T12:00Z"));
  const SubsolarPoint evening = earthSubsolarPoint(at("2024-03-20T18:00Z"));
  EXPECT_NEAR(std::remainder(noon.lon - evening.lon, 360.0), 90.0, kDegrees);
}

TEST(SceneSun, AFixedSunWinsOverTheDate) {
  const SubsolarPoint fixed{120.0, -10.0};
  EXPECT_EQ(sceneSun(Body{}, at("2024-03-20"), fixed), fixed);
}

TEST(SceneSun, TheDatePlacesTheEarthsSunOnly) {
  EXPECT_EQ(sceneSun(Body{}, at("2024-03-20"), std::nullopt), earthSubsolarPoint(at("2024-03-20")));
  EXPECT_FALSE(sceneSun(Body{"Mars", 3389500.0}, at("2024-03-20"), std::nullopt));
  EXPECT_FALSE(sceneSun(Body{}, std::nullopt, std::nullopt));
}

TEST(SunDirection, PointsAtTheSubsolarPoint) {
  const glm::dvec3 overGreenwich = sunDirection({0.0, 0.0}), overThePole = sunDirection({45.0, 90.0});
  EXPECT_NEAR(overGreenwich.x, 1.0, 1e-12);
  EXPECT_NEAR(overThePole.z, 1.0, 1e-12);
}

}  // namespace
}  // namespace strata
