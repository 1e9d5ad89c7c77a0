#include "cube_bintree.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace strata::bdam {
namespace {

// Each face's outward normal and its s and t axes, right-handed (s x t = normal): +x, -x, +y, -y, +z, -z.
struct FaceAxes {
  glm::dvec3 normal, s, t;
};
constexpr std::array<FaceAxes, kCubeFaces> kFaces = {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                                      {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                                      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
                                                      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                                      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                                      {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}}};

// The equi-angular warp, odd and exact at 0 and +-1 (where double's tan(pi / 4) is not), so that an edge two faces
// share, met at s from one and at t or -t from the other, gives the same vector.
double warp(double s) {
  const double magnitude = std::abs(s) == 1.0 ? 1.0 : std::tan(std::numbers::pi / 4.0 * std::abs(s));
  return std::copysign(magnitude, s);
}

// The roots' triangles: half 0 has its right angle at (1, -1), half 1 at (-1, 1); both share the diagonal.
FaceTriangle rootTriangle(int half) {
  return half == 0 ? FaceTriangle{{1, -1}, {1, 1}, {-1, -1}} : FaceTriangle{{-1, 1}, {-1, -1}, {1, 1}};
}

// Which side of the line from `from` to `to` the point lies: positive to the left.
double side(glm::dvec2 from, glm::dvec2 to, glm::dvec2 point) {
  const glm::dvec2 a = to - from, b = point - from;
  return a.x * b.y - a.y * b.x;
}

}  // namespace

int faceOf(const BintreeNode& node) { return node.root / 2; }

FaceTriangle faceTriangle(const BintreeNode& node) {
  if (node.root < 0 || node.root >= kBintreeRoots || node.level < 0 || node.level > kDeepestLevel)
    throw std::invalid_argument("no bintree node at root " + std::to_string(node.root) + ", level " +
                                std::to_string(node.level));
  FaceTriangle triangle = rootTriangle(node.root % 2);
  for (int level = node.level - 1; level >= 0; --level) {
    const glm::dvec2 middle = 0.5 * (triangle.left + triangle.right);
    triangle = (node.path >> level) & 1 ? FaceTriangle{middle, triangle.right, triangle.apex}
                                        : FaceTriangle{middle, triangle.apex, triangle.left};
  }
  return triangle;
}

std::array<BintreeNode, 2> children(const BintreeNode& node) {
  if (node.level >= kDeepestLevel) throw std::invalid_argument("a bintree node of the deepest level has no children");
  return {BintreeNode{node.root, node.level + 1, node.path << 1},
          BintreeNode{node.root, node.level + 1, (node.path << 1) | 1}};
}

FacePoint facePoint(const glm::dvec3& direction) {
  int face = 0;
  for (int f = 1; f < kCubeFaces; ++f)
    if (glm::dot(direction, kFaces[std::size_t(f)].normal) > glm::dot(direction, kFaces[std::size_t(face)].normal))
      face = f;
  const FaceAxes& axes = kFaces[std::size_t(face)];
  const double along = glm::dot(direction, axes.normal);
  const auto unwarp = [along](double across) { return std::atan(across / along) * 4.0 / std::numbers::pi; };
  return {face, {unwarp(glm::dot(direction, axes.s)), unwarp(glm::dot(direction, axes.t))}};
}

BintreeNode nodeContaining(const glm::dvec3& direction, int level) {
  const auto [face, point] = facePoint(direction);
  BintreeNode node{2 * face + (side({-1, -1}, {1, 1}, point) <= 0.0 ? 0 : 1), 0, 0};
  for (int l = 0; l < level; ++l) {
    const FaceTriangle triangle = faceTriangle(node);
    const glm::dvec2 middle = 0.5 * (triangle.left + triangle.right);
    // Child 0 holds the apex and `left`: the side of the line from the middle to the apex where `left` lies.
    node =
        children(node)[side(middle, triangle.apex, point) * side(middle, triangle.apex, triangle.left) >= 0.0 ? 0 : 1];
  }
  return node;
}

glm::dvec3 cubeDirection(int face, glm::dvec2 faceCoordinates) {
  const FaceAxes& axes = kFaces.at(std::size_t(face));
  return glm::normalize(axes.normal + warp(faceCoordinates.x) * axes.s + warp(faceCoordinates.y) * axes.t);
}

}  // namespace strata::bdam
