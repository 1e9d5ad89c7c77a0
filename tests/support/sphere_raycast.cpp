#include "sphere_raycast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/constants.hpp>

namespace strata::test {
namespace {

// The eye-space unit direction of the ray through the centre of pixel (x, y).
glm::dvec3 eyeRay(const View& view, double x, double y) {
  const double tanHalf = std::tan(view.verticalFov / 2.0), aspect = double(view.width) / view.height;
  const double ndcX = (x + 0.5) / view.width * 2.0 - 1.0, ndcY = 1.0 - (y + 0.5) / view.height * 2.0;
  return glm::normalize(glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0));
}

// The same in planet-fixed axes.
glm::dvec3 pixelRay(const View& view, double x, double y) {
  return glm::transpose(view.planetToEye) * eyeRay(view, x, y);
}

// How far along the ray from the eye along `d` it enters the sphere of `radius`, and leaves it.
std::optional<std::pair<double, double>> sphereCrossings(const View& view, const glm::dvec3& d, double radius) {
  const double b = glm::dot(view.eye, d), c = glm::dot(view.eye, view.eye) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0 || -b + std::sqrt(discriminant) < 0.0) return std::nullopt;
  return std::pair{-b - std::sqrt(discriminant), -b + std::sqrt(discriminant)};
}

SurfaceHit hitAt(const View& view, const glm::dvec3& point, const glm::dvec3& d) {
  const glm::dvec3 n = glm::normalize(point);
  return {glm::degrees(std::atan2(n.y, n.x)), glm::degrees(std::asin(n.z)), -glm::dot(n, d),
          glm::length(point - view.eye)};
}

}  // namespace

std::optional<SurfaceHit> raycastSphere(const View& view, double radius, double x, double y) {
  const glm::dvec3 d = pixelRay(view, x, y);
  const auto crossings = sphereCrossings(view, d, radius);
  if (!crossings || crossings->first < 0.0) return std::nullopt;
  return hitAt(view, view.eye + crossings->first * d, d);
}

std::optional<SurfaceHit> raycastTerrain(const View& view, double radius,
                                         const std::function<double(double lon, double lat)>& height, double highest,
                                         double step, double x, double y, double* radiusAt) {
  const glm::dvec3 d = pixelRay(view, x, y);
  const auto crossings = sphereCrossings(view, d, radius + highest);
  if (!crossings) return std::nullopt;
  const auto above = [&](double t) {  // m of the ray above the terrain at t
    const glm::dvec3 point = view.eye + t * d;
    const SurfaceHit where = hitAt(view, point, d);
    return glm::length(point) - radius - height(where.lon, where.lat);
  };
  double t = std::max(crossings->first, 0.0);
  while (t < crossings->second && above(t + step) > 0.0) t += step;
  if (t >= crossings->second) return std::nullopt;
  double low = t, high = t + step;
  while (high - low > 1e-3) (above(0.5 * (low + high)) > 0.0 ? low : high) = 0.5 * (low + high);
  if (radiusAt) *radiusAt = glm::length(view.eye + high * d);
  return hitAt(view, view.eye + high * d, d);
}

double rayDistance(const View& view, float depth, double x, double y) {
  if (depth <= 0.0f) return std::numeric_limits<double>::infinity();
  return view.near / double(depth) / -eyeRay(view, x, y).z;
}

double discRadiusPixels(const View& view, double radius, double distance) {
  const double focalPixels = view.height / 2.0 / std::tan(view.verticalFov / 2.0);
  return focalPixels * std::tan(std::asin(radius / distance));
}

}  // namespace strata::test
