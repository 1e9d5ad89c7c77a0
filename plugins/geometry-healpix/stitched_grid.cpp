#include "stitched_grid.hpp"

#include <stdexcept>

namespace strata::healpix {
namespace {

// The vertex that stands for (column, row) when the edges in `coarser` are stitched: an odd vertex of such
// an edge gives way to the even one before it.
std::uint32_t stitched(int cells, unsigned coarser, int column, int row) {
  const bool onEdge[4] = {row == 0, column == cells, row == cells, column == 0};
  if ((coarser & 1u) && onEdge[0] && column % 2 == 1) --column;
  if ((coarser & 4u) && onEdge[2] && column % 2 == 1) --column;
  if ((coarser & 2u) && onEdge[1] && row % 2 == 1) --row;
  if ((coarser & 8u) && onEdge[3] && row % 2 == 1) --row;
  return std::uint32_t(row * (cells + 1) + column);
}

}  // namespace

std::vector<std::uint32_t> stitchedGridIndices(int cells) {
  if (cells < 2 || cells % 2 != 0) throw std::invalid_argument("a stitched grid needs an even number of cells");
  std::vector<std::uint32_t> indices;
  indices.reserve(kEdgeSets * 6 * std::size_t(cells) * std::size_t(cells));
  for (unsigned coarser = 0; coarser < kEdgeSets; ++coarser)
    for (int row = 0; row < cells; ++row)
      for (int column = 0; column < cells; ++column) {
        const std::uint32_t lowerLeft = stitched(cells, coarser, column, row);
        const std::uint32_t lowerRight = stitched(cells, coarser, column + 1, row);
        const std::uint32_t upperRight = stitched(cells, coarser, column + 1, row + 1);
        const std::uint32_t upperLeft = stitched(cells, coarser, column, row + 1);
        indices.insert(indices.end(), {lowerLeft, lowerRight, upperRight, lowerLeft, upperRight, upperLeft});
      }
  return indices;
}

}  // namespace strata::healpix
