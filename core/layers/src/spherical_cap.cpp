#include <strata/plugin/spherical_cap.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace strata {

glm::dvec3 directionOf(glm::dvec2 lonlat) {
  return {std::cos(lonlat.y) * std::cos(lonlat.x), std::cos(lonlat.y) * std::sin(lonlat.x), std::sin(lonlat.y)};
}

glm::dvec2 lonlatOf(const glm::dvec3& direction) {
  return {std::atan2(direction.y, direction.x), std::atan2(direction.z, std::hypot(direction.x, direction.y))};
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

bool SphericalCap::meets(const SphericalCap& other) const {
  return angleBetween(centre, other.centre) <= angle + other.angle;
}

SphericalCap SphericalCap::widened(double by) const { return {centre, std::min(angle + by, std::numbers::pi)}; }

SphericalCap capAround(std::span<const glm::dvec3> directions) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& direction : directions) sum += direction;
  const double length = glm::length(sum);
  if (length == 0.0) return {glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi};  // no side to centre on
  SphericalCap cap{sum / length, 0.0};
  for (const glm::dvec3& direction : directions) cap.angle = std::max(cap.angle, angleBetween(cap.centre, direction));
  return cap;
}

// The smallest cap holding both: centred on the great circle through the two centres, between their far edges.
SphericalCap joined(const SphericalCap& a, const SphericalCap& b) {
  const double apart = angleBetween(a.centre, b.centre);
  if (apart + b.angle <= a.angle) return a;
  if (apart + a.angle <= b.angle) return b;
  const double angle = 0.5 * (apart + a.angle + b.angle);
  if (angle >= std::numbers::pi || apart == 0.0)
    return {a.centre, std::min(std::max(angle, a.angle), std::numbers::pi)};
  // Turn a's centre toward b's by (angle - a.angle), in their common plane.
  const glm::dvec3 toward = glm::normalize(b.centre - glm::dot(a.centre, b.centre) * a.centre);
  const double turn = angle - a.angle;
  return {glm::normalize(std::cos(turn) * a.centre + std::sin(turn) * toward), angle};
}

}  // namespace strata
