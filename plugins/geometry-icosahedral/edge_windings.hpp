#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "subdivision_table.hpp"

namespace strata::icosahedral {

// Bits of a patch's coarse-edge mask, as Patch::coarseEdges holds them: bit e is set when the neighbour
// across the edge from corner e to corner e + 1 is one level coarser. In grid terms (subdivision_table.hpp)
// edge 0 is b = 0, edge 1 is a + b = N, edge 2 is a = 0.
constexpr unsigned kEdgeWindingCount = 8;

// Where one winding lies in the element buffer: what a DrawElementsIndirectCommand takes.
struct IndexRange {
  std::uint32_t first = 0;  // first index
  std::uint32_t count = 0;  // indices, three per triangle
};

// The eight edge windings of [Kooima 2008, §3.4.1] for one subdivision depth,
// in one element array whose indices number the vertices as the subdivision table does. A coarse edge is
// wound at half resolution: it never references the odd vertices on it, so its triangle edges along the
// patch edge are those of the coarser neighbour and no crack opens. The three fine triangles touching an
// odd edge vertex become two, one of them spanning the even vertices on either side; where two coarse
// edges meet, the corner's four fine triangles become two. Triangles are counter-clockwise when the
// corners v0, v1, v2 are (from outside the sphere). At depth 0 there are no odd vertices, and every
// winding is the patch's one triangle: against a coarser neighbour its corner then lies on the middle of
// the neighbour's edge, a T-junction that only depth 1 or more avoids.
class EdgeWindings {
 public:
  explicit EdgeWindings(const SubdivisionTable& table);

  const std::vector<std::uint32_t>& indices() const { return indices_; }
  IndexRange range(unsigned coarseEdges) const { return ranges_.at(coarseEdges); }  // 0 to 7

 private:
  std::vector<std::uint32_t> indices_;
  std::array<IndexRange, kEdgeWindingCount> ranges_;
};

}  // namespace strata::icosahedral
