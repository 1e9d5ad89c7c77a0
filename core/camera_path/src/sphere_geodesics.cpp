#include "sphere_geodesics.hpp"

#include <cmath>
#include <numbers>

#include <strata/camera.hpp>

namespace strata::paths {
namespace {

// Below this arc (rad; 6e-6 m on the Earth) slerp's sines vanish and a normalised chord is as exact.
constexpr double kTinyArc = 1e-12;
// Points closer to antipodal than this (rad; 64 m on the Earth) have no well-conditioned great circle.
constexpr double kAntipodalMargin = 1e-5;

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

double arcAngle(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double u) {
  const double angle = arcAngle(a, b);
  if (angle < kTinyArc) return glm::normalize(a + (b - a) * u);
  return (std::sin((1.0 - u) * angle) * a + std::sin(u * angle) * b) / std::sin(angle);
}

glm::dvec3 logarithm(const glm::dvec3& p, const glm::dvec3& q) {
  const glm::dvec3 across = q - glm::dot(p, q) * p;
  const double length = glm::length(across);
  if (length == 0.0) return glm::dvec3(0.0);
  return across * (arcAngle(p, q) / length);
}

glm::dvec3 exponential(const glm::dvec3& p, const glm::dvec3& v) {
  const double angle = glm::length(v);
  if (angle < kTinyArc) return glm::normalize(p + v);
  return std::cos(angle) * p + std::sin(angle) * (v / angle);
}

bool antipodal(const glm::dvec3& a, const glm::dvec3& b) {
  return arcAngle(a, b) > std::numbers::pi - kAntipodalMargin;
}

glm::dvec2 lonLatDegrees(const glm::dvec3& unit) {
  double lon = degrees(std::atan2(unit.y, unit.x));
  if (lon >= 180.0) lon -= 360.0;
  return {lon, degrees(std::atan2(unit.z, std::hypot(unit.x, unit.y)))};
}

glm::dvec3 unitVectorDegrees(double lon, double lat) { return unitNormal(radians(lon), radians(lat)); }

}  // namespace strata::paths
