#pragma once
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace strata::bdam {

// The planet's partition in P-BDAM [Cignoni et al. 2003, §4.1]: "a cubical projection, 6 tiles = 6 cube faces, 12
// bintrees (2 per face)". Each face is split along its diagonal into two right triangles, the roots; a node splits
// at its hypotenuse's midpoint into two right triangles of half its area (BDAM's hierarchy of right triangles,
// §3), so that a node meets one of its own level across its hypotenuse, on its face or the next, and finer ones
// across its legs. Corners are face coordinates (s, t) in [-1, 1]^2, dyadic fractions that double holds exactly at
// any level a planet needs.
//
// Face coordinates map to the sphere by the equi-angular cube, s -> tan(pi s / 4): its cells are within 1.42 of each
// other's area where the plain gnomonic cube's differ by 5.2, and the paper resampled its Mars data to the cube
// "maintaining roughly the same number of points" (§6). Points of an edge two faces share map to the same bits from
// either face.
struct BintreeNode {
  int root = 0;            // 0 to 11: face root / 2, its half root % 2
  int level = 0;           // 0 for a root
  std::uint64_t path = 0;  // the child taken at each level below the root, the latest in the lowest bit
  bool operator==(const BintreeNode&) const = default;
};

// A node's right triangle in its face's coordinates: the right angle at `apex`, the hypotenuse from `left` to
// `right`, counter-clockwise seen from outside the body.
struct FaceTriangle {
  glm::dvec2 apex, left, right;
};

inline constexpr int kCubeFaces = 6;
inline constexpr int kBintreeRoots = 12;
inline constexpr int kDeepestLevel = 62;  // a path's bits

int faceOf(const BintreeNode& node);
FaceTriangle faceTriangle(const BintreeNode& node);
// Its two halves, split at the hypotenuse's midpoint: child 0 has the old apex and `left`, child 1 `right` and the
// apex; each child's right angle is at that midpoint.
std::array<BintreeNode, 2> children(const BintreeNode& node);

// The unit vector of face `face`'s point (s, t), planet-fixed (+z north, +x at longitude 0), in double.
glm::dvec3 cubeDirection(int face, glm::dvec2 faceCoordinates);

// The face a planet-fixed unit vector points at most nearly along, and its face coordinates there (the warp
// undone): cubeDirection's inverse.
struct FacePoint {
  int face = 0;
  glm::dvec2 coordinates{0.0};
};
FacePoint facePoint(const glm::dvec3& direction);

// The node of `level` whose triangle holds `direction` (a planet-fixed unit vector): on the face it points at most
// nearly along, then the child on its side of each split (a point on a split, the first child).
BintreeNode nodeContaining(const glm::dvec3& direction, int level);

}  // namespace strata::bdam
