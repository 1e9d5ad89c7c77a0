#pragma once
#include <glm/glm.hpp>
#include <strata/body.hpp>
#include <strata/date.hpp>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The Moon seen from the Earth's centre: ecliptic longitude and latitude of the date (deg) and distance (m).
struct MoonPosition {
  double lon = 0.0;
  double lat = 0.0;
  double distance = 0.0;
};

// Where the Moon stands at `utc`, from the Astronomical Almanac's low-precision formulas: 0.3 degrees in
// longitude, 0.2 in latitude and about 0.2 per cent in distance from 1950 to 2050 [Almanac 2024, §D].
MoonPosition moonPosition(DayNumber utc);

// The Moon's place in a scene whose axes are the Earth's planet-fixed ones (`bodies:`, orbit: moon): its centre,
// and axes with x toward the Earth's centre and z toward the ecliptic's north pole (made perpendicular to x).
// Those are the Moon's mean-Earth axes but for its pole's 1.5 degrees from the ecliptic's and the libration
// (up to 8 degrees), which move the near side's features on the disc as seen from the Earth.
BodyPlacement moonPlacement(DayNumber utc);

}  // namespace strata
STRATA_EXPORTS_END
