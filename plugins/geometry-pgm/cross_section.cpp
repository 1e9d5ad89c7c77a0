#include "cross_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strata::pgm {

CrossSection crossSection(double eyeDistance, double primaryRadius, double secondaryRadius, double zeta) {
  const double primaryTangent = tangentAngle(eyeDistance, primaryRadius);
  return {.eyeDistance = eyeDistance,
          .primaryRadius = primaryRadius,
          .altitude = eyeDistance - primaryRadius,
          .primaryTangent = primaryTangent,
          .secondaryRadius = secondaryRadius,
          .secondaryTangent = tangentAngle(eyeDistance, secondaryRadius),
          .blendStart = zeta * primaryTangent};
}

double tangentAngle(double eyeDistance, double radius) { return std::asin(radius / eyeDistance); }

namespace {

// delta = (c^2 - 1) u^2 with c = 1 + eps: by how much c u's cosine squared falls short of u's.
double shortfall(double relativeAltitude, double sinRay) {
  return relativeAltitude * (2.0 + relativeAltitude) * sinRay * sinRay;
}

}  // namespace

bool misses(double relativeAltitude, double sinRay, double cosRay) {
  return cosRay < 0.0 || cosRay * cosRay < shortfall(relativeAltitude, sinRay);
}

// sin(asin(c u) - asin(u)) = c u w - u sqrt(1 - c^2 u^2), and 1 - c^2 u^2 = w^2 - delta; c w is w + eps w,
// and w - sqrt(w^2 - delta) is delta / (w + sqrt(w^2 - delta)), without the difference of near equals.
double frontNormalAngle(double relativeAltitude, double sinRay, double cosRay) {
  const double delta = shortfall(relativeAltitude, sinRay);
  const double exitCosine = std::sqrt(std::max(cosRay * cosRay - delta, 0.0));
  return std::asin(sinRay * (relativeAltitude * cosRay + delta / (cosRay + exitCosine)));
}

// A tangent ray may round past its sphere by an ulp: its argument is kept at 1.
double backNormalAngle(double eyeDistance, double radius, double rayAngle) {
  return std::numbers::pi - std::asin(std::min(eyeDistance / radius * std::sin(rayAngle), 1.0)) - rayAngle;
}

double blendFactor(const CrossSection& view, double rayAngle) {
  if (rayAngle <= view.blendStart) return 0.0;
  return std::min((rayAngle - view.blendStart) / (view.primaryTangent - view.blendStart), 1.0);
}

double secondaryNormalAngle(const CrossSection& view, double blend) {
  const double rayAngle = view.blendStart + blend * (view.secondaryTangent - view.blendStart);
  const double sine = view.eyeDistance / view.secondaryRadius * std::sin(rayAngle);
  return std::asin(std::clamp(sine, -1.0, 1.0)) - rayAngle;
}

double normalAngle(const CrossSection& view, double sinRay, double cosRay) {
  const double primary = frontNormalAngle(view.altitude / view.primaryRadius, sinRay, cosRay);
  const double blend = blendFactor(view, std::atan2(sinRay, cosRay));
  if (blend == 0.0 || view.secondaryRadius <= 0.0) return primary;
  return primary + blend * (secondaryNormalAngle(view, blend) - primary);
}

namespace {

// A unit vector perpendicular to `unit`: the plane of a ray straight up from the nadir.
glm::dvec3 anyPerpendicular(const glm::dvec3& unit) {
  const glm::dvec3 axis = std::abs(unit.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(unit, axis));
}

}  // namespace

SpherePoint castRay(const CrossSection& view, const glm::dvec3& ray, const glm::dvec3& nadir) {
  const glm::dvec3 antinadir = -nadir;
  // The cross-section basis of [Mahsman 2010, §3.6.2]: i = n, j = i x ray, k = j x i; |j| = sin(omega).
  const glm::dvec3 across = glm::cross(nadir, ray);
  double sinRay = glm::length(across), cosRay = glm::dot(ray, nadir);
  const bool hit = !misses(view.altitude / view.primaryRadius, sinRay, cosRay);
  if (hit && sinRay < kNadirSine) return {true, antinadir, -view.altitude * antinadir};
  const glm::dvec3 side = sinRay >= kNadirSine ? glm::cross(across, nadir) / sinRay : anyPerpendicular(nadir);
  if (!hit) {
    sinRay = std::sin(view.primaryTangent);
    cosRay = std::cos(view.primaryTangent);
  }
  const double gamma = normalAngle(view, sinRay, cosRay);
  const double halfSine = std::sin(0.5 * gamma);
  return {hit, antinadir * std::cos(gamma) + side * std::sin(gamma),
          -(view.altitude + 2.0 * view.primaryRadius * halfSine * halfSine) * antinadir +
              view.primaryRadius * std::sin(gamma) * side};
}

}  // namespace strata::pgm
