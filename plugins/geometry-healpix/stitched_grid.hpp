#pragma once
#include <cstdint>
#include <vector>

namespace strata::healpix {

// The proxy grid every node is drawn from [Westerteiger et al. 2011, §3.2.4]: cells x cells squares of
// (cells + 1)^2 vertices, numbered row by row from the node's (x, y) = (0, 0) corner, two triangles a cell
// over the diagonal from its lower left to its upper right corner, counter-clockwise in (x, y), which faces
// outwards on every base face.
//
// An edge next to a node one level coarser must not use its odd vertices, which the coarser node does
// not have: there they would stand as T-junctions and open cracks (the paper leaves these open: in
// [Westerteiger et al. 2011, §3] only same-level neighbours meet without gaps, by their shared samples).
// For each of the 16 sets of such edges (bit e for edge e: 0 at y = 0, 1 at x = 1, 2 at y = 1, 3 at x = 0)
// the grid's triangles are listed with each odd vertex of those edges replaced by the even one before it
// along the edge: the two triangles that met there collapse to lines, which the rasteriser drops, and the
// rest fill the strip up to the coarse edge without a gap.
constexpr unsigned kEdgeSets = 16;

// 16 sections of 6 cells^2 indices, section m for the set of coarser edges m. cells must be even.
std::vector<std::uint32_t> stitchedGridIndices(int cells);

}  // namespace strata::healpix
