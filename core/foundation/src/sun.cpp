// Where the sun stands overhead: the Earth's subsolar point from the date, or the scene's fixed one.
#include <strata/sun.hpp>

#include <cmath>

#include <glm/trigonometric.hpp>
#include <strata/camera.hpp>
#include <strata/named_bodies.hpp>

#include "earth_rotation.hpp"

namespace strata {
namespace {

bool isEarth(const Body& body) { return findNamedBody(body.name) == findNamedBody("Earth"); }

}  // namespace

// [Almanac 2024, §C5]: the Sun's mean longitude L and mean anomaly g, its ecliptic longitude lambda, turned by
// the obliquity and Greenwich mean sidereal time [USNO GMST] into the Earth's axes (earthFixedOfEcliptic). UT
// stands for TT: the minute between them moves the Sun 0.0007 degrees. The equation of the equinoxes (at most
// 0.005 degrees) is left out.
SubsolarPoint earthSubsolarPoint(DayNumber utc) {
  const double n = utc - kJ2000;
  const double meanLongitude = 280.460 + 0.9856474 * n;
  const double meanAnomaly = glm::radians(357.528 + 0.9856003 * n);
  const double eclipticLongitude =
      glm::radians(meanLongitude + 1.915 * std::sin(meanAnomaly) + 0.020 * std::sin(2.0 * meanAnomaly));
  const glm::dvec2 overhead = lonLatOf(earthFixedOfEcliptic(eclipticLongitude, 0.0, n));
  return {wrapDegrees(glm::degrees(overhead.x)), glm::degrees(overhead.y)};
}

std::optional<SubsolarPoint> sceneSun(const Body& body, const std::optional<DayNumber>& date,
                                      const std::optional<SubsolarPoint>& fixed) {
  if (fixed) return fixed;
  if (date && isEarth(body)) return earthSubsolarPoint(*date);
  return std::nullopt;
}

Error sunUnknown(const SourceLocation& where, const std::string& asked) {
  return Error(where, asked + ", but the scene does not say where the sun is",
               "give the scene a date and time (date: 2024-03-20T12:00; the sun follows it on the Earth and the Moon "
               "in a scene of both), or the point the sun stands over (sun: {lon: 0, lat: 0})");
}

glm::dvec3 sunDirection(const SubsolarPoint& sun) { return unitNormal(glm::radians(sun.lon), glm::radians(sun.lat)); }

}  // namespace strata
