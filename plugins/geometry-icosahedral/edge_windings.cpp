#include "edge_windings.hpp"

#include <algorithm>
#include <iterator>

namespace strata::icosahedral {
namespace {

using GridTriangle = std::array<GridPoint, 3>;

bool coarse(unsigned coarseEdges, int edge) { return ((coarseEdges >> edge) & 1u) != 0; }

// Whether the point is an odd vertex of a coarse edge, one the coarser neighbour does not have. On an
// edge both coordinates are even at the even vertices (N is even from depth 1 on).
bool oddOnCoarseEdge(GridPoint p, int n, unsigned coarseEdges) {
  if (p.a % 2 == 0 && p.b % 2 == 0) return false;
  return (coarse(coarseEdges, 0) && p.b == 0) || (coarse(coarseEdges, 1) && p.a + p.b == n) ||
         (coarse(coarseEdges, 2) && p.a == 0);
}

// The full-resolution triangulation, row by row, less the triangles that touch an odd vertex of a coarse
// edge.
std::vector<GridTriangle> fineTriangles(int n, unsigned coarseEdges) {
  std::vector<GridTriangle> triangles;
  const auto keep = [&](const GridTriangle& t) {
    if (std::ranges::none_of(t, [&](GridPoint p) { return oddOnCoarseEdge(p, n, coarseEdges); }))
      triangles.push_back(t);
  };
  for (int b = 0; b < n; ++b)
    for (int a = 0; a + b < n; ++a) {
      keep({{{a, b}, {a + 1, b}, {a, b + 1}}});
      if (a + b + 1 < n) keep({{{a + 1, b}, {a + 1, b + 1}, {a, b + 1}}});
    }
  return triangles;
}

// The grid point at (x, y) in the frame of an edge, where the edge runs from (0, 0) to (N, 0) and the
// patch lies at y >= 0. The frame is the patch's rotation that takes corner v0 to the edge's first
// corner: a symmetry of the triangulation that keeps its triangles counter-clockwise.
GridPoint inEdgeFrame(int edge, GridPoint p, int n) {
  for (int turn = 0; turn < edge; ++turn) p = {n - p.a - p.b, p.a};
  return p;
}

// The half-resolution strip along a coarse edge, in the edge's frame. Over each pair of segments from x
// to x + 2 the three fine triangles touching the odd vertex x + 1 become (x,0) (x+2,0) (x+1,1), spanning
// the even vertices, and (x,0) (x+1,1) (x,1). Where the edge before is coarse too, the first pair's second
// triangle would use that edge's odd vertex (0,1): it is left out. Where the edge after is coarse, the last
// pair becomes (N-2,0) (N,0) (N-2,1) alone. So the four fine triangles at a corner between two coarse edges
// become the first triangle of one edge and the last of the other.
std::vector<GridTriangle> coarseStrip(int edge, int n, unsigned coarseEdges) {
  const bool previousCoarse = coarse(coarseEdges, (edge + 2) % 3), nextCoarse = coarse(coarseEdges, (edge + 1) % 3);
  std::vector<GridTriangle> triangles;
  const auto add = [&](GridPoint p, GridPoint q, GridPoint r) {
    triangles.push_back({inEdgeFrame(edge, p, n), inEdgeFrame(edge, q, n), inEdgeFrame(edge, r, n)});
  };
  for (int x = 0; x < n; x += 2) {
    if (x + 2 == n && nextCoarse) {
      add({x, 0}, {x + 2, 0}, {x, 1});
      continue;
    }
    add({x, 0}, {x + 2, 0}, {x + 1, 1});
    if (x > 0 || !previousCoarse) add({x, 0}, {x + 1, 1}, {x, 1});
  }
  return triangles;
}

std::vector<GridTriangle> windingTriangles(int n, unsigned coarseEdges) {
  // Depth 0 has no odd vertices; at depth 1 with every edge coarse only the corners remain.
  if (n == 1 || (n == 2 && coarseEdges == kEdgeWindingCount - 1)) return {{{{0, 0}, {n, 0}, {0, n}}}};
  std::vector<GridTriangle> triangles = fineTriangles(n, coarseEdges);
  for (int edge = 0; edge < 3; ++edge)
    if (coarse(coarseEdges, edge)) std::ranges::copy(coarseStrip(edge, n, coarseEdges), std::back_inserter(triangles));
  return triangles;
}

}  // namespace

EdgeWindings::EdgeWindings(const SubdivisionTable& table) {
  for (unsigned coarseEdges = 0; coarseEdges < kEdgeWindingCount; ++coarseEdges) {
    const auto first = std::uint32_t(indices_.size());
    for (const GridTriangle& triangle : windingTriangles(table.segments(), coarseEdges))
      for (GridPoint corner : triangle) indices_.push_back(table.indexOf(corner));
    ranges_[coarseEdges] = {first, std::uint32_t(indices_.size()) - first};
  }
}

}  // namespace strata::icosahedral
