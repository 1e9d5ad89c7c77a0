// Where the sun stands overhead: the Earth's subsolar point from the date, or the scene's fixed one.
#include <strata/sun.hpp>

#include <cmath>

#include <glm/trigonometric.hpp>
#include <strata/camera.hpp>
#include <strata/named_bodies.hpp>

namespace strata {
namespace {

// J2000.0 (2000-01-01T12:00) on the day count of strata/date.hpp, which starts at midnight.
constexpr double kJ2000 = 0.5;

double wrapDegrees(double angle) {
  const double wrapped = std::fmod(angle + 180.0, 360.0);
  return (wrapped < 0.0 ? wrapped + 360.0 : wrapped) - 180.0;
}

bool isEarth(const Body& body) { return findNamedBody(body.name) == findNamedBody("Earth"); }

}  // namespace

// [Almanac 2024, §C5]: the Sun's mean longitude L and mean anomaly g, its ecliptic longitude lambda, the
// obliquity epsilon, then right ascension and declination. UT stands for TT: the minute between them moves
// the Sun 0.0007 degrees. The subsolar longitude is the right ascension less Greenwich mean sidereal time
// [USNO GMST]; the equation of the equinoxes (at most 0.005 degrees) is left out.
SubsolarPoint earthSubsolarPoint(DayNumber utc) {
  const double n = utc - kJ2000;
  const double meanLongitude = 280.460 + 0.9856474 * n;
  const double meanAnomaly = glm::radians(357.528 + 0.9856003 * n);
  const double eclipticLongitude =
      glm::radians(meanLongitude + 1.915 * std::sin(meanAnomaly) + 0.020 * std::sin(2.0 * meanAnomaly));
  const double obliquity = glm::radians(23.439 - 0.0000004 * n);
  const double rightAscension =
      std::atan2(std::cos(obliquity) * std::sin(eclipticLongitude), std::cos(eclipticLongitude));
  const double declination = std::asin(std::sin(obliquity) * std::sin(eclipticLongitude));
  const double siderealHours = 18.697374558 + 24.06570982441908 * n;
  return {wrapDegrees(glm::degrees(rightAscension) - 15.0 * siderealHours), glm::degrees(declination)};
}

std::optional<SubsolarPoint> sceneSun(const Body& body, const std::optional<DayNumber>& date,
                                      const std::optional<SubsolarPoint>& fixed) {
  if (fixed) return fixed;
  if (date && isEarth(body)) return earthSubsolarPoint(*date);
  return std::nullopt;
}

glm::dvec3 sunDirection(const SubsolarPoint& sun) { return unitNormal(glm::radians(sun.lon), glm::radians(sun.lat)); }

}  // namespace strata
