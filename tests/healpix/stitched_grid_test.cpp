// The stitched proxy grid (plugins/geometry-healpix/stitched_grid.hpp): for each of the 16 sets of coarser
// edges, its triangles cover the node's square once, all counter-clockwise, and along a coarser edge its
// outline runs from even vertex to even vertex only, as the coarser neighbour's edge does, so the two meet
// without a T-junction.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <utility>

#include <glm/glm.hpp>

#include "stitched_grid.hpp"

namespace strata::healpix {
namespace {

constexpr int kCells = 8;

glm::ivec2 latticeOf(std::uint32_t index) { return {int(index) % (kCells + 1), int(index) / (kCells + 1)}; }

// Twice the signed area of a triangle of lattice points.
int doubledArea(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Which side an outline edge of the square lies on, or -1 inside: 0 at y = 0, 1 at x = cells, 2 at y = cells,
// 3 at x = 0.
int sideOf(glm::ivec2 a, glm::ivec2 b) {
  if (a.y == 0 && b.y == 0) return 0;
  if (a.x == kCells && b.x == kCells) return 1;
  if (a.y == kCells && b.y == kCells) return 2;
  if (a.x == 0 && b.x == 0) return 3;
  return -1;
}

TEST(HealpixStitchedGrid, EveryEdgeSetCoversTheSquareAndMeetsItsNeighbours) {
  const std::vector<std::uint32_t> indices = stitchedGridIndices(kCells);
  const std::size_t perSet = 6 * kCells * kCells;
  ASSERT_EQ(indices.size(), kEdgeSets * perSet);
  for (unsigned coarser = 0; coarser < kEdgeSets; ++coarser) {
    SCOPED_TRACE(coarser);
    int doubledTotal = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;  // to find the outline
    for (std::size_t t = coarser * perSet; t < (coarser + 1) * perSet; t += 3) {
      const std::array<std::uint32_t, 3> triangle{indices[t], indices[t + 1], indices[t + 2]};
      const int area = doubledArea(latticeOf(triangle[0]), latticeOf(triangle[1]), latticeOf(triangle[2]));
      ASSERT_GE(area, 0) << "a triangle turned clockwise";
      if (area == 0) continue;  // collapsed at a stitched vertex: the rasteriser drops it
      doubledTotal += area;
      for (int k = 0; k < 3; ++k) ++directedEdges[{triangle[k], triangle[(k + 1) % 3]}];
    }
    EXPECT_EQ(doubledTotal, 2 * kCells * kCells);  // with no triangle turned over, the square once
    std::array<int, 4> outlineSteps{};             // the longest outline edge on each side, in lattice steps
    for (const auto& [edge, count] : directedEdges) {
      EXPECT_EQ(count, 1) << "two triangles overlap";
      if (directedEdges.contains({edge.second, edge.first})) continue;  // shared inside the square
      const glm::ivec2 a = latticeOf(edge.first), b = latticeOf(edge.second);
      const int side = sideOf(a, b);
      ASSERT_GE(side, 0) << "an outline edge inside the square";
      outlineSteps[std::size_t(side)] =
          std::max(outlineSteps[std::size_t(side)], std::abs(b.x - a.x) + std::abs(b.y - a.y));
      if (coarser & (1u << side)) {
        EXPECT_TRUE(a.x % 2 == 0 && a.y % 2 == 0 && b.x % 2 == 0 && b.y % 2 == 0);
      }
    }
    for (int side = 0; side < 4; ++side) EXPECT_EQ(outlineSteps[std::size_t(side)], (coarser & (1u << side)) ? 2 : 1);
  }
}

}  // namespace
}  // namespace strata::healpix
