#pragma once
#include <glm/vec3.hpp>
#include <optional>
#include <strata/body.hpp>
#include <strata/date.hpp>
#include <strata/error.hpp>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Where the sun stands overhead on a body: the subsolar point, in degrees (longitude east positive).
struct SubsolarPoint {
  double lon = 0.0;
  double lat = 0.0;
  bool operator==(const SubsolarPoint&) const = default;
};

// The Earth's subsolar point at `utc` from the Astronomical Almanac's low-precision formulas for the Sun
// (0.01 degree from 1950 to 2050) and the mean sidereal time [Almanac 2024, §C5; USNO GMST].
SubsolarPoint earthSubsolarPoint(DayNumber utc);

// The scene's sun: `fixed` (the pipeline's `sun:`) where given, else the date's where the body's motion is
// known (the Earth's); none otherwise.
std::optional<SubsolarPoint> sceneSun(const Body& body, const std::optional<DayNumber>& date,
                                      const std::optional<SubsolarPoint>& fixed);

// The refusal of a setting that asks for the sun (`asked`: "shading: sun") where the scene places none, at
// `where`, with the fix: a date, or a fixed sun.
Error sunUnknown(const SourceLocation& where, const std::string& asked);

// The planet-fixed unit vector toward the sun from the body's centre (docs/architecture.md, "Conventions").
glm::dvec3 sunDirection(const SubsolarPoint& sun);

}  // namespace strata
STRATA_EXPORTS_END
