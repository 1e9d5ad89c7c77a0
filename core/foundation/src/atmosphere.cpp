#include <strata/atmosphere.hpp>

#include <algorithm>
#include <cmath>

#include <glm/exponential.hpp>
#include <glm/gtc/constants.hpp>

namespace strata {

double rayleighPhase(double nu) { return 3.0 / (16.0 * glm::pi<double>()) * (1.0 + nu * nu); }

double miePhase(double nu, double g) {
  const double g2 = g * g;
  return 3.0 / (8.0 * glm::pi<double>()) * (1.0 - g2) * (1.0 + nu * nu) /
         ((2.0 + g2) * std::pow(1.0 + g2 - 2.0 * g * nu, 1.5));
}

AtmosphereModel::AtmosphereModel(const Atmosphere& air, double ground)
    : air_(air), bottom_(ground), top_(ground + air.thickness) {}

double AtmosphereModel::density(double altitude, double scaleHeight) { return std::exp(-altitude / scaleHeight); }

glm::dvec3 AtmosphereModel::rayleighScatteringAt(double r) const {
  return air_.rayleighScattering * density(r - bottom_, air_.rayleighScaleHeight);
}

double AtmosphereModel::mieScatteringAt(double r) const {
  return air_.mieScattering * density(r - bottom_, air_.mieScaleHeight);
}

glm::dvec3 AtmosphereModel::extinctionAt(double r) const {
  return rayleighScatteringAt(r) + glm::dvec3(air_.mieExtinction * density(r - bottom_, air_.mieScaleHeight));
}

glm::dvec3 AtmosphereModel::scatteringAt(double r) const { return rayleighScatteringAt(r) + mieScatteringAt(r); }

double AtmosphereModel::distanceToTop(double r, double mu) const {
  const double discriminant = r * r * (mu * mu - 1.0) + top_ * top_;
  return std::max(0.0, -r * mu + std::sqrt(std::max(0.0, discriminant)));
}

double AtmosphereModel::distanceToGround(double r, double mu) const {
  const double discriminant = r * r * (mu * mu - 1.0) + bottom_ * bottom_;
  return std::max(0.0, -r * mu - std::sqrt(std::max(0.0, discriminant)));
}

bool AtmosphereModel::meetsGround(double r, double mu) const {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + bottom_ * bottom_ >= 0.0;
}

double AtmosphereModel::distanceToBoundary(double r, double mu) const {
  return meetsGround(r, mu) ? distanceToGround(r, mu) : distanceToTop(r, mu);
}

glm::dvec3 AtmosphereModel::opticalDepth(double r, double mu, double length, int steps) const {
  const double step = length / steps;
  glm::dvec3 depth(0.0);
  for (int i = 0; i < steps; ++i) {
    const double t = (i + 0.5) * step;
    depth += extinctionAt(std::sqrt(t * t + 2.0 * r * mu * t + r * r)) * step;
  }
  return depth;
}

glm::dvec3 AtmosphereModel::transmittanceToTop(double r, double mu, int steps) const {
  return glm::exp(-opticalDepth(r, mu, distanceToTop(r, mu), steps));
}

}  // namespace strata
