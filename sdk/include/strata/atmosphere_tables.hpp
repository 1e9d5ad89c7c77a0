#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <strata/atmosphere.hpp>
#include <strata/export.hpp>
#include <vector>

STRATA_EXPORTS_BEGIN
namespace strata {

// A table of RGB values over the unit square, stored at width x height points spaced evenly from edge to edge
// (texel centres, as a GL texture of that size samples them with linear filtering), read bilinearly.
struct AtmosphereTable {
  int width = 0, height = 0;
  std::vector<glm::vec3> values;  // row by row, x fastest

  glm::dvec3 at(glm::dvec2 unit) const;  // bilinear at (x, y) in [0, 1]^2, clamped to it
};

// The transmittance table's coordinates of the ray (r, mu) that does not meet the ground, and back [Bruneton
// 2008, §4], in the form of its published reimplementation (Bruneton 2017): x follows the distance to the top
// of the air between its least and greatest at r, y the distance to the horizon, so that the horizon, where
// transmittance changes fastest, lies at the table's edge and every texel holds a ray that reaches the top.
glm::dvec2 transmittanceCoordinates(const AtmosphereModel& model, double r, double mu);
glm::dvec2 rayOfTransmittanceCoordinates(const AtmosphereModel& model, glm::dvec2 unit);  // (r, mu)

// The multiple-scattering table's coordinates of radius r and the sun's zenith cosine muSun [Hillaire 2020,
// "Multiple scattering LUT"]: x = muSun from -1 to 1, y = altitude from the ground to the top.
glm::dvec2 multipleScatteringCoordinates(const AtmosphereModel& model, double r, double muSun);

// The tables an atmosphere is drawn with, computed once in double from its model.
struct AtmosphereTables {
  // [Bruneton 2008]'s published implementation's 256 x 64: within 3e-4 of the quadrature between its points.
  static constexpr int kTransmittanceWidth = 256, kTransmittanceHeight = 64;
  // [Hillaire 2020] takes 32 x 32. Across the terminator Psi_ms changes tenfold within 0.1 of the sun's cosine: 32
  // points of it read 11% astray with the sun on the horizon, 64 points 3% (tests/unit/atmosphere_test.cpp).
  static constexpr int kMultipleScatteringSuns = 64, kMultipleScatteringAltitudes = 32;

  AtmosphereTable transmittance;       // to the top of the air, for rays that do not meet the ground
  AtmosphereTable multipleScattering;  // Psi_ms: light scattered twice and more, per unit scattering, for a sun of 1

  // The transmittance to the top of the air along (r, mu) from the table; 0 where the ray meets the ground.
  glm::dvec3 transmittanceToTop(const AtmosphereModel& model, double r, double mu) const;
  glm::dvec3 multipleScatteringAt(const AtmosphereModel& model, double r, double muSun) const;
};

AtmosphereTables makeAtmosphereTables(const AtmosphereModel& model);

// How Psi_ms is summed: directions over the sphere in bands of cosine (half toward the ground, half toward the sky,
// narrowing toward the horizon), times azimuths, and midpoint steps along each. The table's: 8 x 16 directions (the
// paper takes 64) and 20 steps [Hillaire 2020], within 6% of 64 times as many by day; 4 times as many would take
// 4 times the 0.6 s the table takes to make.
struct SphereQuadrature {
  int cosineBands = 8, azimuths = 16, steps = 20;
};

// Psi_ms at radius r under a sun of zenith cosine muSun, summed by `quadrature`, the sun's transmittance read from
// `tables`: the value the multiple-scattering table holds at its points.
glm::dvec3 multipleScatteringFor(const AtmosphereModel& model, const AtmosphereTables& tables, double r, double muSun,
                                 const SphereQuadrature& quadrature = {});

// Light along a ray through the air, for a sun of irradiance 1 (W/m^2 or any unit): what the air scatters toward
// the eye, and the share of what lies behind that reaches it.
struct AirLight {
  glm::dvec3 inscattered{0.0};    // radiance, per unit of the sun's irradiance
  glm::dvec3 transmittance{1.0};  // of the path
};

// The light the air scatters toward `origin` (planet-fixed, m) along the unit `direction` over its first
// `length` m (or to where it leaves the air), lit by a sun in the unit direction `sun`: single scattering by
// Rayleigh's and Mie's phases, the planet's shadow, and multiple scattering from the tables [Hillaire 2020,
// "Rendering the sky"], by `steps` segments, the sun's transmittance at each by `sunSteps` midpoints. What
// shaders/strata/atmosphere.glsl draws, here in double to judge it by.
AirLight airLightAlong(const AtmosphereModel& model, const AtmosphereTables& tables, const glm::dvec3& origin,
                       const glm::dvec3& direction, double length, const glm::dvec3& sun, int steps, int sunSteps);

}  // namespace strata
STRATA_EXPORTS_END
