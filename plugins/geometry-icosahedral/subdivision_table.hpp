#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace strata::icosahedral {

// Deeper patches would hold more than 33153 vertices each; the patch tree refines instead.
constexpr int kDeepestSubdivision = 8;

// nv(d) = (2^d + 1)(2^d + 2) / 2: the vertices of a patch subdivided d times [Kooima 2008, §3.3.1].
int verticesPerPatch(int depth);

// A vertex's place in the patch's triangular grid of N = 2^depth segments per edge, a + b <= N. In the
// flat sense the vertex lies at v0 + a/N (v1 - v0) + b/N (v2 - v0): (0, 0) is corner v0, (N, 0) is v1,
// (0, N) is v2. On the sphere it is the recursive great-circle midpoint that the subdivision makes.
struct GridPoint {
  int a = 0;
  int b = 0;
  bool operator==(const GridPoint&) const = default;
};

// The dependence table of [Kooima 2008, §3.3.1]: every vertex but the three
// corners is made from two parents, and the vertices are numbered breadth first, so that a compute pass
// can fill level L = 1..depth as the index range [nv(L - 1), nv(L)) while reading only indices below
// nv(L - 1). Vertices 0, 1 and 2 are the corners v0, v1, v2. Level L adds the grid points that are
// multiples of s = 2^(depth - L) but not both multiples of 2s, row by row (b, then a).
//
// Parent order: the parents of a level-L vertex lie at point -+ s * direction, the direction being the
// patch edge the pair runs parallel to, taken from its lower-numbered corner: (1, 0) from v0 to v1,
// (0, 1) from v0 to v2, (-1, 1) from v1 to v2. The first parent is the one nearer that corner. A vertex
// on a patch edge has both parents on that edge, so two patches that share an edge and agree on which
// of its corners comes first compute its vertices from the same ordered pairs; where they disagree the
// consumer orders the pair by value.
class SubdivisionTable {
 public:
  explicit SubdivisionTable(int depth);  // 0 to kDeepestSubdivision

  int depth() const { return depth_; }
  int segments() const { return 1 << depth_; }  // N
  int vertexCount() const { return int(grid_.size()); }

  // A corner is its own parent twice: the midpoint of a point with itself is the point, so a pass that
  // reads the table for a corner leaves it unchanged.
  std::array<std::uint32_t, 2> parents(std::uint32_t vertex) const;
  GridPoint gridOf(std::uint32_t vertex) const { return grid_[vertex]; }
  std::uint32_t indexOf(GridPoint point) const;

  // The parent pairs, two per vertex in vertex order: what the compute pass reads from its buffer.
  const std::vector<std::uint32_t>& parentPairs() const { return parentPairs_; }

 private:
  void addLevel(int level);

  int depth_;
  std::vector<GridPoint> grid_;
  std::vector<std::uint32_t> parentPairs_;
  std::vector<std::uint32_t> indexOfPoint_;  // (N + 1)^2, row b then column a
};

}  // namespace strata::icosahedral
