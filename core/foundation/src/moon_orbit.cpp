// The Moon about the Earth, from the Astronomical Almanac's low-precision series.
#include <strata/moon_orbit.hpp>

#include <cmath>
#include <span>

#include <glm/gtc/constants.hpp>
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

// The sum of `terms` at `centuries`; `quarter`: of cosines (each argument a quarter turn on), else of sines.
double periodicSum(std::span<const Term> terms, double centuries, bool quarter = false) {
  double sum = 0.0;
  for (const Term& term : terms)
    sum += term.amplitude * std::sin(glm::radians(term.phase + term.rate * centuries + (quarter ? 90.0 : 0.0)));
  return sum;
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
  const double lon = 218.32 + 481267.881 * centuries + periodicSum(kLongitude, centuries);
  const double lat = periodicSum(kLatitude, centuries);
  const double parallax = 0.9508 + periodicSum(kParallax, centuries, true);
  return {wrapDegrees(lon), lat, kEarthEquatorialRadius / std::sin(glm::radians(parallax))};
}

BodyPlacement moonPlacement(DayNumber utc) {
  const double days = utc - kJ2000;
  const MoonPosition moon = moonPosition(utc);
  const glm::dvec3 centre = earthFixedOfEcliptic(glm::radians(moon.lon), glm::radians(moon.lat), days) * moon.distance;
  const glm::dvec3 eclipticPole = earthFixedOfEcliptic(0.0, glm::half_pi<double>(), days);
  const glm::dvec3 x = -glm::normalize(centre);
  const glm::dvec3 z = glm::normalize(eclipticPole - x * glm::dot(eclipticPole, x));
  return {centre, glm::dmat3(x, glm::cross(z, x), z)};
}

}  // namespace strata
