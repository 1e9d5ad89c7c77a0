#include <strata/atmosphere_tables.hpp>

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "air_segment.hpp"

namespace strata {
namespace {

// Light scattered twice and more is taken as isotropic [Hillaire 2020, "Multiple scattering LUT"].
const double kIsotropicPhase = 1.0 / (4.0 * glm::pi<double>());

constexpr int kTransmittanceSteps = 500;  // [Bruneton 2008]'s published implementation's 500 samples

// The square root of r^2 - b^2, as (r - b)(r + b) for precision near b.
double rootOfDifference(double r, double b) { return std::sqrt(std::max(0.0, (r - b) * (r + b))); }

// What light reaches `origin` along `direction` from the air and the ground below, for a sun of 1 in `sun`:
// the second order of scattering (isotropic), and the share of light the air transfers to `origin` by one
// scattering from each point, the f_ms of the paper.
struct SecondOrder {
  glm::dvec3 light{0.0}, transfer{0.0};
};

SecondOrder secondOrderAlong(const AtmosphereModel& model, const AtmosphereTables& tables, const glm::dvec3& origin,
                             const glm::dvec3& direction, const glm::dvec3& sun, int steps) {
  const double r = glm::length(origin), mu = glm::dot(origin, direction) / r;
  const double length = model.distanceToBoundary(r, mu), step = length / steps;
  SecondOrder along;
  glm::dvec3 transmittance(1.0);
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 point = origin + (i + 0.5) * step * direction;
    const double radius = glm::length(point);
    const glm::dvec3 extinction = model.extinctionAt(radius);
    const glm::dvec3 scattered = transmittance * model.scatteringAt(radius) * scatteredOverSegment(extinction, step);
    along.light +=
        scattered * tables.transmittanceToTop(model, radius, glm::dot(point, sun) / radius) * kIsotropicPhase;
    along.transfer += scattered;
    transmittance *= glm::exp(-extinction * step);
  }
  if (model.meetsGround(r, mu)) {
    const glm::dvec3 ground = glm::normalize(origin + length * direction);
    const double muSun = glm::dot(ground, sun);
    along.light += transmittance * model.air().groundAlbedo / glm::pi<double>() * std::max(muSun, 0.0) *
                   tables.transmittanceToTop(model, model.bottom(), muSun);
  }
  return along;
}

// A table of `width` x `height` values, `value` of each point's coordinates in [0, 1]^2.
template <class Value>
AtmosphereTable tableOf(int width, int height, Value value) {
  AtmosphereTable table{width, height, {}};
  table.values.reserve(std::size_t(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      table.values.push_back(glm::vec3(value(glm::dvec2(double(i) / (width - 1), double(j) / (height - 1)))));
  return table;
}

}  // namespace

// The second order of scattering from every direction times 1 / (1 - f_ms), the sum of the orders beyond as a
// geometric series [Hillaire 2020, "Multiple scattering LUT"]. Half the bands of cosine look toward the ground and
// half toward the sky, each half's bands narrowing quadratically toward the horizon: just above it rays cross the
// most air and the light peaks, just below it they meet the ground, and bands even over the sphere converged slowly
// there (tests/unit/atmosphere_test.cpp).
glm::dvec3 multipleScatteringFor(const AtmosphereModel& model, const AtmosphereTables& tables, double r, double muSun,
                                 const SphereQuadrature& quadrature) {
  const glm::dvec3 origin(0.0, 0.0, r), sun(std::sqrt(std::max(0.0, 1.0 - muSun * muSun)), 0.0, muSun);
  const double horizon = -rootOfDifference(r, model.bottom()) / r;
  const int half = std::max(1, quadrature.cosineBands / 2), azimuths = quadrature.azimuths;
  glm::dvec3 light(0.0), transfer(0.0);
  for (int band = 0; band < 2 * half; ++band) {
    // s from 0 at the horizon to 1 at the nadir or the zenith; the cosine moves as s^2.
    const double far = band < half ? -1.0 : 1.0, s0 = double(band % half) / half, s1 = double(band % half + 1) / half;
    const double c0 = horizon + (far - horizon) * s0 * s0, c1 = horizon + (far - horizon) * s1 * s1;
    const double cosine = 0.5 * (c0 + c1), sine = std::sqrt(1.0 - cosine * cosine);
    const double solidAngle = 2.0 * glm::pi<double>() * std::abs(c1 - c0) / azimuths;
    for (int a = 0; a < azimuths; ++a) {
      const double azimuth = (a + 0.5) * 2.0 * glm::pi<double>() / azimuths;
      const glm::dvec3 direction(sine * std::cos(azimuth), sine * std::sin(azimuth), cosine);
      const SecondOrder along = secondOrderAlong(model, tables, origin, direction, sun, quadrature.steps);
      light += along.light * kIsotropicPhase * solidAngle;
      transfer += along.transfer * kIsotropicPhase * solidAngle;
    }
  }
  return light / (1.0 - transfer);
}

glm::dvec3 AtmosphereTable::at(glm::dvec2 unit) const {
  const double x = std::clamp(unit.x, 0.0, 1.0) * (width - 1), y = std::clamp(unit.y, 0.0, 1.0) * (height - 1);
  const int i = std::min(int(x), width - 2), j = std::min(int(y), height - 2);
  const auto value = [&](int di, int dj) { return glm::dvec3(values[std::size_t(j + dj) * width + i + di]); };
  return glm::mix(glm::mix(value(0, 0), value(1, 0), x - i), glm::mix(value(0, 1), value(1, 1), x - i), y - j);
}

glm::dvec2 transmittanceCoordinates(const AtmosphereModel& model, double r, double mu) {
  const double horizon = rootOfDifference(model.top(), model.bottom()), rho = rootOfDifference(r, model.bottom());
  const double least = model.top() - r, most = rho + horizon;
  const double d = model.distanceToTop(r, mu);
  return {most > least ? (d - least) / (most - least) : 0.0, rho / horizon};
}

glm::dvec2 rayOfTransmittanceCoordinates(const AtmosphereModel& model, glm::dvec2 unit) {
  const double horizon = rootOfDifference(model.top(), model.bottom()), rho = horizon * unit.y;
  const double r = std::sqrt(rho * rho + model.bottom() * model.bottom());
  const double least = model.top() - r, most = rho + horizon, d = least + unit.x * (most - least);
  const double mu = d <= 0.0 ? 1.0 : (horizon * horizon - rho * rho - d * d) / (2.0 * r * d);
  return {r, std::clamp(mu, -1.0, 1.0)};
}

glm::dvec2 multipleScatteringCoordinates(const AtmosphereModel& model, double r, double muSun) {
  return glm::clamp(glm::dvec2(0.5 * muSun + 0.5, (r - model.bottom()) / (model.top() - model.bottom())), 0.0, 1.0);
}

glm::dvec3 AtmosphereTables::transmittanceToTop(const AtmosphereModel& model, double r, double mu) const {
  if (model.meetsGround(r, mu)) return glm::dvec3(0.0);
  return transmittance.at(transmittanceCoordinates(model, r, mu));
}

glm::dvec3 AtmosphereTables::multipleScatteringAt(const AtmosphereModel& model, double r, double muSun) const {
  return multipleScattering.at(multipleScatteringCoordinates(model, r, muSun));
}

AtmosphereTables makeAtmosphereTables(const AtmosphereModel& model) {
  AtmosphereTables tables;
  tables.transmittance =
      tableOf(AtmosphereTables::kTransmittanceWidth, AtmosphereTables::kTransmittanceHeight, [&](glm::dvec2 unit) {
        const glm::dvec2 ray = rayOfTransmittanceCoordinates(model, unit);
        return model.transmittanceToTop(ray.x, ray.y, kTransmittanceSteps);
      });
  tables.multipleScattering = tableOf(
      AtmosphereTables::kMultipleScatteringSuns, AtmosphereTables::kMultipleScatteringAltitudes, [&](glm::dvec2 unit) {
        return multipleScatteringFor(model, tables, model.bottom() + unit.y * (model.top() - model.bottom()),
                                     2.0 * unit.x - 1.0);
      });
  return tables;
}

}  // namespace strata
