// The light of the sky along one ray, in double: what shaders/strata/atmosphere.glsl draws, to judge it by.
#include <algorithm>
#include <cmath>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <strata/atmosphere_tables.hpp>

#include "air_segment.hpp"

namespace strata {
namespace {

// Where the ray from `origin` along the unit `direction` lies within a sphere of `radius` about the centre:
// its distances in and out, or none.
bool withinSphere(const glm::dvec3& origin, const glm::dvec3& direction, double radius, double& in, double& out) {
  const double b = glm::dot(origin, direction), c = glm::dot(origin, origin) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  in = -b - root;
  out = -b + root;
  return out > 0.0;
}

}  // namespace

AirLight airLightAlong(const AtmosphereModel& model, const AtmosphereTables& tables, const glm::dvec3& origin,
                       const glm::dvec3& direction, double length, const glm::dvec3& sun, int steps, int sunSteps) {
  double in = 0.0, out = 0.0;
  if (!withinSphere(origin, direction, model.top(), in, out)) return {};
  double groundIn = 0.0, groundOut = 0.0;
  if (withinSphere(origin, direction, model.bottom(), groundIn, groundOut) && groundIn > 0.0)
    out = std::min(out, groundIn);
  const double start = std::max(in, 0.0), end = std::min(out, length);
  if (end <= start) return {};
  const double nu = glm::dot(direction, sun), step = (end - start) / steps;
  const double rayleigh = rayleighPhase(nu), mie = miePhase(nu, model.air().mieAsymmetry);
  AirLight light;
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 point = origin + (start + (i + 0.5) * step) * direction;
    const double r = glm::length(point), muSun = glm::dot(point, sun) / r;
    const glm::dvec3 sunlight =
        model.meetsGround(r, muSun) ? glm::dvec3(0.0) : model.transmittanceToTop(r, muSun, sunSteps);
    const glm::dvec3 molecules = model.rayleighScatteringAt(r);
    const double aerosols = model.mieScatteringAt(r);
    const glm::dvec3 source = (molecules * rayleigh + aerosols * mie) * sunlight +
                              (molecules + aerosols) * tables.multipleScatteringAt(model, r, muSun);
    const glm::dvec3 extinction = model.extinctionAt(r);
    light.inscattered += light.transmittance * source * scatteredOverSegment(extinction, step);
    light.transmittance *= glm::exp(-extinction * step);
  }
  return light;
}

}  // namespace strata
