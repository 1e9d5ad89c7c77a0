#include "pipeline/scene_placement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/trigonometric.hpp>
#include <strata/moon_orbit.hpp>

namespace strata {
namespace {

constexpr double kAstronomicalUnit = 1.495978707e11;  // m [IAU 2012 B2]

}  // namespace

BodyPlacement placementOf(const SceneBody& body, const std::optional<DayNumber>& date) {
  switch (body.orbit) {
    case BodyOrbit::Fixed: return {body.position, glm::dmat3(1.0)};
    case BodyOrbit::Moon:
      if (!date) throw std::logic_error("a body on an orbit was placed without the scene's date");
      return moonPlacement(*date);
  }
  return {};
}

SubsolarPoint sunOver(const SubsolarPoint& sun, const BodyPlacement& placement) {
  const glm::dvec3 toSun = sunDirection(sun) * kAstronomicalUnit - placement.centre;
  const glm::dvec3 inBody = glm::normalize(glm::transpose(placement.axes) * toSun);
  return {glm::degrees(std::atan2(inBody.y, inBody.x)), glm::degrees(std::asin(std::clamp(inBody.z, -1.0, 1.0)))};
}

}  // namespace strata
