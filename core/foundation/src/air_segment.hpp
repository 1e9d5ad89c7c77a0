#pragma once
// What a segment of air of uniform extinction passes on, shared by the tables and the sky's light.
#include <glm/exponential.hpp>
#include <glm/vec3.hpp>

namespace strata {

// The in-scattered light's integral over a segment `length` m long through air of extinction `extinction` (1/m)
// per unit source: (1 - T) / extinction, T the segment's transmittance, so that light scattered in the segment
// is also dimmed within it and no step size adds energy [Hillaire 2020, "Rendering the sky"].
inline glm::dvec3 scatteredOverSegment(const glm::dvec3& extinction, double length) {
  glm::dvec3 integral;
  for (int c = 0; c < 3; ++c)
    integral[c] = extinction[c] > 1e-30 ? -std::expm1(-extinction[c] * length) / extinction[c] : length;
  return integral;
}

}  // namespace strata
