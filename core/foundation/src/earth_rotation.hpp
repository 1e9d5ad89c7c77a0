#pragma once
// The Earth's orientation at a date, which the sun's and the Moon's places in its planet-fixed axes share.
#include <glm/glm.hpp>
#include <strata/date.hpp>

namespace strata {

// J2000.0 (2000-01-01T12:00) on the day count of strata/date.hpp, which starts at midnight.
constexpr double kJ2000 = 0.5;

// The obliquity of the ecliptic, deg, `days` after J2000.0 [Almanac 2024, §C5].
double eclipticObliquity(double days);

// Greenwich mean sidereal time as an angle, deg, `days` (UT) after J2000.0 [USNO GMST]: how far the Earth's
// planet-fixed axes have turned from the equinox's.
double greenwichSiderealAngle(double days);

// Wraps an angle in degrees into [-180, 180).
double wrapDegrees(double angle);

// The direction of ecliptic longitude and latitude (rad) of the date, `days` after J2000.0, in the Earth's
// planet-fixed axes: into the equator and equinox of the date by the obliquity, then about the pole by the
// sidereal angle. What the sun's and the Moon's places are turned by.
glm::dvec3 earthFixedOfEcliptic(double lon, double lat, double days);

// Longitude and latitude (rad) of a direction from the centre, of any length but 0.
glm::dvec2 lonLatOf(const glm::dvec3& direction);

}  // namespace strata
