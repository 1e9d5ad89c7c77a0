// The detail field (detail_field.hpp): its lattice is the icosahedron subdivided three times, bit for bit as the
// patch tree subdivides it, so the tree's vertices find their lattice vertex exactly; a lattice triangle's grid
// lists its vertices in the subdivision table's order; smoothing raises values until neighbours lie within the
// ratio, and lowers none.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "detail_field.hpp"
#include "patch_topology.hpp"

namespace strata::icosahedral {
namespace {

TEST(DetailField, TheTreesVerticesAreTheLatticesBitForBit) {
  const DetailField field(1.0);
  EXPECT_EQ(field.vertexCount(), 642);
  PatchTopology topology;
  for (int level = 0; level < DetailField::kLevel; ++level)
    for (std::int32_t id = 0; id < std::int32_t(topology.capacity()); ++id)
      if (topology[id].alive && topology[id].leaf() && topology[id].level == level) topology.split(id);
  std::set<int> found;
  for (std::int32_t id = 0; id < std::int32_t(topology.capacity()); ++id)
    for (const std::uint32_t corner : topology[id].corners) {
      const int v = field.vertexAt(topology.normalOf(corner));
      const glm::dvec3 tilted = glm::normalize(topology.normalOf(corner) + glm::dvec3(1e-3, 0.0, 0.0));
      EXPECT_EQ(field.vertexAt(tilted), v) << "the nearest, where no vertex holds the bits";
      found.insert(v);
    }
  EXPECT_EQ(found.size(), 642u);
}

TEST(DetailField, AFacesGridListsItsLatticeVerticesInTheTablesOrder) {
  const DetailField field(1.0);
  PatchTopology topology;
  const std::vector<int> grid = field.gridOf(topology.cornersOf(0), 0);
  ASSERT_EQ(grid.size(), std::size_t(DetailField::kPatchValues));
  EXPECT_EQ(std::set<int>(grid.begin(), grid.end()).size(), grid.size()) << "45 distinct vertices";
  for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(grid[c], field.vertexAt(topology.cornersOf(0)[c]));
  EXPECT_EQ(field.gridOf(topology.cornersOf(0), DetailField::kLevel).size(), 3u) << "a lattice triangle: its corners";
}

// One vertex asking for 64 where all else asks for 1: its neighbours are raised to 16, theirs to 4, and the
// values fall by 4 a step until they reach 1.
TEST(DetailField, SmoothingRaisesNeighboursToWithinTheRatio) {
  const DetailField field(1.0);
  std::vector<double> wanted(std::size_t(field.vertexCount()), 1.0);
  wanted[100] = 64.0;
  const std::vector<double> smoothed = field.smoothed(wanted);
  for (std::size_t v = 0; v < wanted.size(); ++v) EXPECT_GE(smoothed[v], wanted[v]);
  EXPECT_EQ(smoothed[100], 64.0);
  const std::vector<double> values = smoothed;
  EXPECT_EQ(std::ranges::count(values, 16.0), 6) << "a lattice vertex away from the icosahedron's has six neighbours";
  EXPECT_GT(std::ranges::count(values, 1.0), 500);
}

}  // namespace
}  // namespace strata::icosahedral
