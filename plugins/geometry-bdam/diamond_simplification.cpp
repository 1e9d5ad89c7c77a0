#include "diamond_simplification.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "displaced_triangle.hpp"
#include "patch_order.hpp"

namespace strata::bdam {
namespace {

using PositionKey = std::array<std::uint64_t, 3>;

PositionKey keyOf(const glm::dvec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y), std::bit_cast<std::uint64_t>(p.z)};
}

// The edge of its half's triangle a child's vertex lies on, as the corner opposite it, or -1. Child 0 is (middle,
// apex, left), child 1 (middle, right, apex) (cube_bintree.hpp): a child's hypotenuse is one of the half's legs, and
// its leg from the middle to `left` or `right` half of the half's hypotenuse.
int edgeOfHalf(int child, const DisplacedVertex& v) {
  if (v.b1 + v.b2 == kBarycentricSteps) return child == 0 ? 2 : 1;
  if ((child == 0 ? v.b1 : v.b2) == 0) return 0;
  return -1;
}

// The diamond's children as one mesh: each half's vertices welded where its two children share them, each half
// with its own copy of the diagonal.
struct DiamondMesh {
  std::vector<glm::dvec3> positions;
  std::vector<int> half, edge;  // per vertex
  std::vector<std::uint32_t> indices;
};

DiamondMesh joined(const Diamond& diamond, const std::array<DisplacedPatch, 4>& children, double radius) {
  DiamondMesh mesh;
  const std::array<BintreeNode, 4> nodes = diamond.children();
  std::array<std::map<PositionKey, std::uint32_t>, 2> welded;
  for (int c = 0; c < 4; ++c) {
    const DisplacedTriangle triangle = displacedTriangle(nodes[std::size_t(c)], radius);
    std::vector<std::uint32_t> local;
    for (const DisplacedVertex& v : children[std::size_t(c)].vertices) {
      const glm::dvec3 p = triangle.point(v);
      const auto [at, added] = welded[std::size_t(c / 2)].try_emplace(keyOf(p), std::uint32_t(mesh.positions.size()));
      if (added) {
        mesh.positions.push_back(p);
        mesh.half.push_back(c / 2);
        mesh.edge.push_back(edgeOfHalf(c % 2, v));
      }
      local.push_back(at->second);
    }
    for (std::uint32_t i : children[std::size_t(c)].indices) mesh.indices.push_back(local.at(i));
  }
  return mesh;
}

// Half the triangles, by meshoptimizer's quadric-error edge collapse with the outline locked, in float about the
// diamond's centre. In the body's own frame, so that the quadrics weigh the sphere's curve with the relief: against a
// height field about the tangent plane (the sphere left out) the patches' errors came out 2 to 3 times larger.
std::vector<std::uint32_t> simplified(const DiamondMesh& mesh) {
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& p : mesh.positions) centre += p / double(mesh.positions.size());
  std::vector<float> positions;
  for (const glm::dvec3& p : mesh.positions)
    for (int k = 0; k < 3; ++k) positions.push_back(float(p[k] - centre[k]));
  std::vector<std::uint32_t> kept(mesh.indices.size());
  const std::size_t target = mesh.indices.size() / 6 * 3;
  kept.resize(meshopt_simplify(kept.data(), mesh.indices.data(), mesh.indices.size(), positions.data(),
                               mesh.positions.size(), 3 * sizeof(float), target, 1.0f, meshopt_SimplifyLockBorder,
                               nullptr));
  return kept;
}

// The diagonal's vertices each half kept, as positions: the same, or the simplification broke the diamond.
void checkDiagonal(const DiamondMesh& mesh, const std::vector<std::uint32_t>& kept) {
  std::array<std::set<PositionKey>, 2> diagonal;
  for (std::uint32_t i : kept)
    if (mesh.edge[i] == 0) diagonal[std::size_t(mesh.half[i])].insert(keyOf(mesh.positions[i]));
  if (diagonal[0] != diagonal[1])
    throw std::logic_error("the diamond's halves kept different vertices of their shared hypotenuse");
}

DisplacedPatch halfPatch(const DiamondMesh& mesh, const std::vector<std::uint32_t>& kept, int half,
                         const DisplacedTriangle& triangle) {
  DisplacedPatch patch;
  std::map<std::uint32_t, std::uint32_t> renumbered;
  for (std::size_t t = 0; t < kept.size(); t += 3) {
    if (mesh.half[kept[t]] != half) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t i = kept[t + k];
      const auto [at, added] = renumbered.try_emplace(i, std::uint32_t(patch.vertices.size()));
      if (added) patch.vertices.push_back(triangle.vertexAt(mesh.positions[i], mesh.edge[i]));
      patch.indices.push_back(at->second);
    }
  }
  return orderedForDrawing(patch);
}

}  // namespace

std::array<DisplacedPatch, 2> simplifiedDiamond(const Diamond& diamond, const std::array<DisplacedPatch, 4>& children,
                                                double radius) {
  const DiamondMesh mesh = joined(diamond, children, radius);
  const std::vector<std::uint32_t> kept = simplified(mesh);
  checkDiagonal(mesh, kept);
  return {halfPatch(mesh, kept, 0, displacedTriangle(diamond.halves[0], radius)),
          halfPatch(mesh, kept, 1, displacedTriangle(diamond.halves[1], radius))};
}

}  // namespace strata::bdam
