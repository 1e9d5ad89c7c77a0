// The Moon about the Earth, from the Astronomical Almanac's low-precision series.
#include <strata/moon_orbit.hpp>

#include <cmath>

#include <glm/trigonometric.hpp>

#include "earth_rotation.hpp"

namespace strata {
namespace {

// The Almanac's unit of the Moon's horizontal parallax: the Earth's equatorial radius, m.
constexpr double kEarthEquatorialRadius = 6378140.0;

// One periodic term: amplitude x sin (or cos) of (phase + rate T), degrees, T in Julian centuries.
struct Term {
  double amplitude, phase, rate;
};

double sineSeries(const Term* terms, int count, double centuries) {
  double sum = 0.0;
  for (int i = 0; i < count; ++i)
    sum += terms[i].amplitude * std::sin(glm::radians(terms[i].phase + terms[i].rate * centuries));
  return sum;
}

double cosineSeries(const Term* terms, int count, double centuries) {
  double sum = 0.0;
  for (int i = 0; i < count; ++i)
    sum += terms[i].amplitude * std::cos(glm::radians(terms[i].phase + terms[i].rate * centuries));
  return sum;
}

// A direction given in the equator and equinox of the date turned into the Earth's planet-fixed axes `days`
// after J2000.0: about the pole by the sidereal angle.
glm::dvec3 earthFixed(const glm::dvec3& equatorial, double days) {
  const double angle = glm::radians(greenwichSiderealAngle(days));
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * equatorial.x + s * equatorial.y, -s * equatorial.x + c * equatorial.y, equatorial.z};
}

// Ecliptic longitude and latitude (rad) as a unit vector in the equator and equinox of the date.
glm::dvec3 equatorialOfEcliptic(double lon, double lat, double obliquity) {
  const double ce = std::cos(obliquity), se = std::sin(obliquity);
  return {std::cos(lat) * std::cos(lon), ce * std::cos(lat) * std::sin(lon) - se * std::sin(lat),
          se * std::cos(lat) * std::sin(lon) + ce * std::sin(lat)};
}

}  // namespace

// [Almanac 2024, §D, "low-precision formulas for geocentric coordinates of the Moon"]: the longitude's six
// terms, the latitude's four, the horizontal parallax's four; the distance is one equatorial radius over the
// parallax's sine.
MoonPosition moonPosition(DayNumber utc) {
  static constexpr Term kLongitude[] = {{6.29, 135.0, 477198.87}, {-1.27, 259.3, -413335.36},
                                        {0.66, 235.7, 890534.22}, {0.21, 269.9, 954397.74},
                                        {-0.19, 357.5, 35999.05}, {-0.11, 186.5, 966404.03}};
  static constexpr Term kLatitude[] = {
      {5.13, 93.3, 483202.02}, {0.28, 228.2, 960400.89}, {-0.28, 318.3, 6003.15}, {-0.17, 217.6, -407332.21}};
  static constexpr Term kParallax[] = {
      {0.0518, 135.0, 477198.87}, {0.0095, 259.3, -413335.36}, {0.0078, 235.7, 890534.22}, {0.0028, 269.9, 954397.74}};
  const double centuries = (utc - kJ2000) / 36525.0;
  const double lon = 218.32 + 481267.881 * centuries + sineSeries(kLongitude, 6, centuries);
  const double lat = sineSeries(kLatitude, 4, centuries);
  const double parallax = 0.9508 + cosineSeries(kParallax, 4, centuries);
  return {wrapDegrees(lon), lat, kEarthEquatorialRadius / std::sin(glm::radians(parallax))};
}

BodyPlacement moonPlacement(DayNumber utc) {
  const double days = utc - kJ2000;
  const double obliquity = glm::radians(eclipticObliquity(days));
  const MoonPosition moon = moonPosition(utc);
  const glm::dvec3 centre =
      earthFixed(equatorialOfEcliptic(glm::radians(moon.lon), glm::radians(moon.lat), obliquity), days) * moon.distance;
  const glm::dvec3 eclipticPole = earthFixed(glm::dvec3(0.0, -std::sin(obliquity), std::cos(obliquity)), days);
  const glm::dvec3 x = -glm::normalize(centre);
  const glm::dvec3 z = glm::normalize(eclipticPole - x * glm::dot(eclipticPole, x));
  return {centre, glm::dmat3(x, glm::cross(z, x), z)};
}

}  // namespace strata
