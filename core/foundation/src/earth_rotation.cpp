#include "earth_rotation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

namespace strata {

double eclipticObliquity(double days) { return 23.439 - 0.0000004 * days; }

double greenwichSiderealAngle(double days) { return 15.0 * (18.697374558 + 24.06570982441908 * days); }

glm::dvec3 earthFixedOfEcliptic(double lon, double lat, double days) {
  const double obliquity = glm::radians(eclipticObliquity(days));
  const double ce = std::cos(obliquity), se = std::sin(obliquity);
  const glm::dvec3 equatorial(std::cos(lat) * std::cos(lon), ce * std::cos(lat) * std::sin(lon) - se * std::sin(lat),
                              se * std::cos(lat) * std::sin(lon) + ce * std::sin(lat));
  const double angle = glm::radians(greenwichSiderealAngle(days));
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * equatorial.x + s * equatorial.y, -s * equatorial.x + c * equatorial.y, equatorial.z};
}

glm::dvec2 lonLatOf(const glm::dvec3& direction) {
  return {std::atan2(direction.y, direction.x), std::asin(std::clamp(direction.z / glm::length(direction), -1.0, 1.0))};
}

double wrapDegrees(double angle) {
  const double wrapped = std::fmod(angle + 180.0, 360.0);
  return (wrapped < 0.0 ? wrapped + 360.0 : wrapped) - 180.0;
}

}  // namespace strata
