#pragma once
#include <optional>

#include <strata/body.hpp>
#include <strata/date.hpp>
#include <strata/export.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/sun.hpp>

// Where the bodies of a scene of several (`bodies:`) stand at a date, and the sun each sees.
// Not part of the SDK: exported from libstrata_core for Strata's own tests.
STRATA_EXPORTS_BEGIN
namespace strata {

// The body's centre and axes in the scene's (the first body's planet-fixed ones): its position, or its orbit
// at `date`. An orbit needs a date; the loader refuses a scene that has an orbit and no date.
BodyPlacement placementOf(const SceneBody& body, const std::optional<DayNumber>& date);

// The point the sun stands over on a body placed at `placement`, `sun` being where it stands over the first
// body: the direction from the body's own centre (the sun taken at one astronomical unit from the first
// body), in the body's axes. From the Moon the Earth's direction to the sun is 0.15 degrees off.
SubsolarPoint sunOver(const SubsolarPoint& sun, const BodyPlacement& placement);

}  // namespace strata
STRATA_EXPORTS_END
