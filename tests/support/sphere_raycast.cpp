#include "sphere_raycast.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace strata::test {

std::optional<SurfaceHit> raycastSphere(const View& view, double radius, double x, double y) {
  const double tanHalf = std::tan(view.verticalFov / 2.0), aspect = double(view.width) / view.height;
  const double ndcX = (x + 0.5) / view.width * 2.0 - 1.0, ndcY = 1.0 - (y + 0.5) / view.height * 2.0;
  const glm::dvec3 inEye = glm::normalize(glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0));
  const glm::dvec3 d = glm::transpose(view.planetToEye) * inEye;
  const double b = glm::dot(view.eye, d), c = glm::dot(view.eye, view.eye) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return std::nullopt;
  const double t = -b - std::sqrt(discriminant);
  if (t < 0.0) return std::nullopt;
  const glm::dvec3 n = glm::normalize(view.eye + t * d);
  return SurfaceHit{glm::degrees(std::atan2(n.y, n.x)), glm::degrees(std::asin(n.z)), -glm::dot(n, d)};
}

double discRadiusPixels(const View& view, double radius, double distance) {
  const double focalPixels = view.height / 2.0 / std::tan(view.verticalFov / 2.0);
  return focalPixels * std::tan(std::asin(radius / distance));
}

}  // namespace strata::test
