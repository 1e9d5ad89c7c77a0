#include "displaced_triangle.hpp"

#include <cmath>

namespace strata::bdam {

glm::dvec3 DisplacedTriangle::flatPoint(double b1, double b2) const {
  return corners[0] + b1 * (corners[1] - corners[0]) + b2 * (corners[2] - corners[0]);
}

glm::dvec3 DisplacedTriangle::normal(double b1, double b2) const {
  return normals[0] + b1 * (normals[1] - normals[0]) + b2 * (normals[2] - normals[0]);
}

glm::dvec3 DisplacedTriangle::point(const DisplacedVertex& vertex) const {
  const double b1 = double(vertex.b1) / kBarycentricSteps, b2 = double(vertex.b2) / kBarycentricSteps;
  return flatPoint(b1, b2) + 0.01 * vertex.centimetres * normal(b1, b2);
}

// |P + h N| = distance: h^2 |N|^2 + 2 h P.N + |P|^2 - distance^2 = 0, the root beside the flat point (the flat
// point lies inside the sphere through the corners, the line leaves it outward along N). Written so that neither
// root cancels: q = -(P.N + sqrt(disc)), h = c / q for the outer root when c < 0.
double DisplacedTriangle::displacementTo(double b1, double b2, double distance) const {
  const glm::dvec3 p = flatPoint(b1, b2), n = normal(b1, b2);
  const double a = glm::dot(n, n), half = glm::dot(p, n), c = (glm::length(p) - distance) * (glm::length(p) + distance);
  const double root = std::sqrt(std::max(half * half - a * c, 0.0));
  return half >= 0.0 ? -c / (half + root) : (root - half) / a;
}

DisplacedTriangle displacedTriangle(const BintreeNode& node, double radius) {
  const FaceTriangle face = faceTriangle(node);
  const int f = faceOf(node);
  const std::array<glm::dvec3, 3> directions = {cubeDirection(f, face.apex), cubeDirection(f, face.left),
                                                cubeDirection(f, face.right)};
  return {{radius * directions[0], radius * directions[1], radius * directions[2]}, directions};
}

}  // namespace strata::bdam
