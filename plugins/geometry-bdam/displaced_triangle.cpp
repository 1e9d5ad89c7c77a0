#include "displaced_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace strata::bdam {
namespace {

bool lexicographicallyLess(const glm::dvec3& a, const glm::dvec3& b) {
  return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

// Corner `i` + w (corner `j` - corner `i`) of `values`, from the lesser corner of the edge (1 - w is exact for a
// lattice point's w), the corners themselves at the ends.
glm::dvec3 alongEdge(const std::array<glm::dvec3, 3>& corners, const std::array<glm::dvec3, 3>& values, int i, int j,
                     double w) {
  if (w == 0.0 || w == 1.0) return values[std::size_t(w == 0.0 ? i : j)];
  if (lexicographicallyLess(corners[std::size_t(j)], corners[std::size_t(i)])) {
    std::swap(i, j);
    w = 1.0 - w;
  }
  const glm::dvec3& from = values[std::size_t(i)];
  return from + w * (values[std::size_t(j)] - from);
}

// P(b) or N(b) for `values` (the corners or the normals), from the edge's ends alone on an edge.
glm::dvec3 interpolated(const std::array<glm::dvec3, 3>& corners, const std::array<glm::dvec3, 3>& values, double b1,
                        double b2) {
  if (b1 == 0.0) return alongEdge(corners, values, 0, 2, b2);
  if (b2 == 0.0) return alongEdge(corners, values, 0, 1, b1);
  if (b1 + b2 == 1.0) return alongEdge(corners, values, 1, 2, b2);
  return values[0] + b1 * (values[1] - values[0]) + b2 * (values[2] - values[0]);
}

// Steps of the lean correction: each shrinks the miss by the normal's lean times the displacement over the
// triangle's size, well under a thousandth for any patch a planet needs.
constexpr int kLeanSteps = 4;

// |P + h N| = distance: h^2 |N|^2 + 2 h P.N + |P|^2 - distance^2 = 0, the root beside the flat point (the flat
// point lies inside the sphere through the corners, the line leaves it outward along N). Written so that neither
// root cancels: q = -(P.N + sqrt(disc)), h = c / q for the outer root when c < 0.
double displacementFrom(const glm::dvec3& p, const glm::dvec3& n, double distance) {
  const double a = glm::dot(n, n), half = glm::dot(p, n), c = (glm::length(p) - distance) * (glm::length(p) + distance);
  const double root = std::sqrt(std::max(half * half - a * c, 0.0));
  return half >= 0.0 ? -c / (half + root) : (root - half) / a;
}

// An edge from its lesser corner: where the flat point on the line through a direction lies along it.
struct CanonicalEdge {
  glm::dvec3 from, to;
  double along(const glm::dvec3& direction) const {  // (from + w (to - from)) x direction = 0
    const glm::dvec3 across = glm::cross(to - from, direction);
    return -glm::dot(glm::cross(from, direction), across) / glm::dot(across, across);
  }
};

}  // namespace

glm::dvec3 DisplacedTriangle::flatPoint(double b1, double b2) const { return interpolated(corners, corners, b1, b2); }

glm::dvec3 DisplacedTriangle::normal(double b1, double b2) const { return interpolated(corners, normals, b1, b2); }

glm::dvec3 DisplacedTriangle::point(const DisplacedVertex& vertex) const {
  const double b1 = double(vertex.b1) / kBarycentricSteps, b2 = double(vertex.b2) / kBarycentricSteps;
  return flatPoint(b1, b2) + 0.01 * vertex.centimetres * normal(b1, b2);
}

double DisplacedTriangle::displacementTo(double b1, double b2, double distance) const {
  return displacementFrom(flatPoint(b1, b2), normal(b1, b2), distance);
}

DisplacedTriangle displacedTriangle(const BintreeNode& node, double radius) {
  const FaceTriangle face = faceTriangle(node);
  const int f = faceOf(node);
  const std::array<glm::dvec3, 3> directions = {cubeDirection(f, face.apex), cubeDirection(f, face.left),
                                                cubeDirection(f, face.right)};
  return {{radius * directions[0], radius * directions[1], radius * directions[2]}, directions};
}

namespace {

// The lattice point nearest a planetocentric point on the edge opposite corner `opposite`: the edge's own
// parameter, from its lesser corner, found and quantised from its corners alone. Returns b1, b2 in steps.
std::array<long, 2> onEdge(const DisplacedTriangle& triangle, const glm::dvec3& point, int opposite) {
  const int i = opposite == 0 ? 1 : 0, j = opposite == 2 ? 1 : 2;
  const bool flipped = triangle.edgeRunsBackwards(opposite);
  const int from = flipped ? j : i, to = flipped ? i : j;
  const CanonicalEdge edge{triangle.corners[std::size_t(from)], triangle.corners[std::size_t(to)]};
  const glm::dvec3 fromNormal = triangle.normals[std::size_t(from)], toNormal = triangle.normals[std::size_t(to)];
  const glm::dvec3 direction = glm::normalize(point);
  const double target = edge.along(direction), distance = glm::length(point);
  double w = target;
  for (int step = 0; step < kLeanSteps; ++step) {
    const glm::dvec3 flat = edge.from + w * (edge.to - edge.from), normal = fromNormal + w * (toNormal - fromNormal);
    w += target - edge.along(glm::normalize(flat + displacementFrom(flat, normal, distance) * normal));
  }
  const long steps = std::clamp(std::lround(w * kBarycentricSteps), 0L, long(kBarycentricSteps));
  std::array<long, 3> weights{0, 0, 0};
  weights[std::size_t(to)] = steps;
  weights[std::size_t(from)] = kBarycentricSteps - steps;
  return {weights[1], weights[2]};
}

// Barycentrics b1, b2 of the flat point on the line through `direction`.
glm::dvec2 flatBarycentrics(const DisplacedTriangle& triangle, const glm::dvec3& direction) {
  const glm::dvec3 e1 = triangle.corners[1] - triangle.corners[0], e2 = triangle.corners[2] - triangle.corners[0];
  const glm::dvec3 n = glm::cross(e1, e2);
  const glm::dvec3 offset =
      direction * (glm::dot(n, triangle.corners[0]) / glm::dot(n, direction)) - triangle.corners[0];
  const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
  const double p = glm::dot(offset, e1), q = glm::dot(offset, e2), determinant = a * c - b * b;
  return {(c * p - b * q) / determinant, (a * q - b * p) / determinant};
}

// The lattice point nearest a planetocentric point inside the triangle, off its edges. Returns b1, b2 in steps.
std::array<long, 2> inside(const DisplacedTriangle& triangle, const glm::dvec3& point) {
  const glm::dvec3 direction = glm::normalize(point);
  const glm::dvec2 target = flatBarycentrics(triangle, direction);
  const double distance = glm::length(point);
  glm::dvec2 b = target;
  for (int step = 0; step < kLeanSteps; ++step) {
    const double h = triangle.displacementTo(b.x, b.y, distance);
    b += target -
         flatBarycentrics(triangle, glm::normalize(triangle.flatPoint(b.x, b.y) + h * triangle.normal(b.x, b.y)));
  }
  // Strictly inside: a point rounded onto an edge would be a vertex there that the patch across it lacks.
  const long second = std::clamp(std::lround(b.y * kBarycentricSteps), 1L, kBarycentricSteps - 2L);
  return {std::clamp(std::lround(b.x * kBarycentricSteps), 1L, kBarycentricSteps - 1L - second), second};
}

}  // namespace

bool DisplacedTriangle::edgeRunsBackwards(int opposite) const {
  const int i = opposite == 0 ? 1 : 0, j = opposite == 2 ? 1 : 2;  // the edge's corners, as interpolated() names them
  return lexicographicallyLess(corners[std::size_t(j)], corners[std::size_t(i)]);
}

DisplacedVertex DisplacedTriangle::vertexAt(const glm::dvec3& point, int edgeOpposite) const {
  const std::array<long, 2> steps = edgeOpposite >= 0 ? onEdge(*this, point, edgeOpposite) : inside(*this, point);
  const double b1 = double(steps[0]) / kBarycentricSteps, b2 = double(steps[1]) / kBarycentricSteps;
  return displacedVertex(b1, b2, displacementTo(b1, b2, glm::length(point)));
}

}  // namespace strata::bdam
