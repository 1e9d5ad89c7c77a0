#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "icosahedron.hpp"

namespace strata::icosahedral {

// The detail scale as a field over the body (docs/geometry.md, "A detail scale for each region"): values at the
// vertices of the icosahedron subdivided kLevel times, the lattice, and between them the recursive midpoints of
// each edge's ends, as the compute pass takes them vertex by vertex. The detail at a vertex depends on the vertex
// alone, whichever patch draws it, so that patches sharing it morph it alike, while rough terrain asks for more
// detail than the smooth ground around it. Neighbouring lattice values differ by at most kNeighbourRatio, so that
// a patch's corners have finished morphing while it exists.
class DetailField {
 public:
  static constexpr int kLevel = 3;                // 642 values, triangles about 8 degrees across
  static constexpr double kNeighbourRatio = 4.0;  // within the 21 a patch's corners allow (docs/geometry.md)
  // The values a patch carries (Patch::details): nv(kLevel), those of its lattice vertices where it is coarser
  // than the lattice, else its corners'.
  static constexpr int kPatchValues = ((1 << kLevel) + 1) * ((1 << kLevel) + 2) / 2;

  explicit DetailField(double initial);

  int vertexCount() const { return int(directions_.size()); }
  const std::vector<double>& values() const { return values_; }
  void assign(std::vector<double> values) { values_ = std::move(values); }
  // The lattice vertex in `direction`: the one whose bits it holds, as the patch tree's own vertices do, else
  // the nearest.
  int vertexAt(const glm::dvec3& direction) const;
  // The lattice vertices of a triangle of level <= kLevel whose corners are lattice vertices, in the order of a
  // SubdivisionTable of depth kLevel - level: the first vertices of any deeper table, whose levels nest. Found
  // once for each triangle and corner order, then kept: the tree asks every frame.
  const std::vector<int>& gridOf(const SphericalTriangle& corners, int level) const;
  // `wanted` raised wherever a neighbour's value over kNeighbourRatio exceeds it, until nowhere does.
  std::vector<double> smoothed(std::vector<double> wanted) const;

 private:
  std::vector<glm::dvec3> directions_;
  std::vector<std::vector<int>> neighbours_;
  std::vector<double> values_;
  std::unordered_map<std::uint64_t, int> byDirection_;            // a hash of a direction's bits, to its vertex
  mutable std::map<std::array<int, 4>, std::vector<int>> grids_;  // gridOf's, by corners' lattice vertices, level
};

}  // namespace strata::icosahedral
