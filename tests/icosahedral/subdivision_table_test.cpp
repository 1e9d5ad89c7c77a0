// The breadth-first dependence table (plugins/geometry-icosahedral/subdivision_table.hpp): the vertex counts of
// [Kooima 2008, §3.3.1]'s table, parents before children and at the ends of their child's grid segment, levels that
// fill consecutive index ranges, and the parent order along shared edges.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

#include "subdivision_table.hpp"

namespace strata::icosahedral {
namespace {

GridPoint midpointOf(GridPoint p, GridPoint q) {
  EXPECT_EQ((p.a + q.a) % 2, 0);
  EXPECT_EQ((p.b + q.b) % 2, 0);
  return {(p.a + q.a) / 2, (p.b + q.b) / 2};
}

TEST(SubdivisionTable, VertexCountsMatchTheDigestsTable) {
  const int expected[] = {3, 6, 15, 45, 153, 561, 2145, 8385};  // [Kooima 2008, §3.3.1]
  for (int depth = 0; depth <= 7; ++depth) {
    EXPECT_EQ(verticesPerPatch(depth), expected[depth]) << "depth " << depth;
    EXPECT_EQ(SubdivisionTable(depth).vertexCount(), expected[depth]) << "depth " << depth;
  }
  EXPECT_EQ(SubdivisionTable(kDeepestSubdivision).vertexCount(), verticesPerPatch(kDeepestSubdivision));
}

TEST(SubdivisionTable, RejectsDepthsOutsideItsRange) {
  EXPECT_THROW(SubdivisionTable(-1), std::invalid_argument);
  EXPECT_THROW(SubdivisionTable(kDeepestSubdivision + 1), std::invalid_argument);
}

TEST(SubdivisionTable, CornersComeFirstAndAreTheirOwnParents) {
  for (int depth = 0; depth <= 5; ++depth) {
    const SubdivisionTable table(depth);
    const int n = table.segments();
    EXPECT_EQ(table.gridOf(0), (GridPoint{0, 0}));
    EXPECT_EQ(table.gridOf(1), (GridPoint{n, 0}));
    EXPECT_EQ(table.gridOf(2), (GridPoint{0, n}));
    for (std::uint32_t corner = 0; corner < 3; ++corner)
      EXPECT_EQ(table.parents(corner), (std::array<std::uint32_t, 2>{corner, corner}));
  }
}

TEST(SubdivisionTable, NumbersEveryGridPointOnce) {
  for (int depth = 0; depth <= 6; ++depth) {
    const SubdivisionTable table(depth);
    std::set<std::pair<int, int>> seen;
    for (std::uint32_t i = 0; i < std::uint32_t(table.vertexCount()); ++i) {
      const GridPoint p = table.gridOf(i);
      ASSERT_TRUE(p.a >= 0 && p.b >= 0 && p.a + p.b <= table.segments());
      EXPECT_TRUE(seen.insert({p.a, p.b}).second);
      EXPECT_EQ(table.indexOf(p), i);
    }
  }
  EXPECT_THROW(SubdivisionTable(2).indexOf({3, 2}), std::out_of_range);
}

TEST(SubdivisionTable, ParentsPrecedeTheirChildAtTheEndsOfItsGridSegment) {
  for (int depth = 1; depth <= kDeepestSubdivision; ++depth) {
    const SubdivisionTable table(depth);
    for (std::uint32_t i = 3; i < std::uint32_t(table.vertexCount()); ++i) {
      const auto [j, k] = table.parents(i);
      EXPECT_LT(j, i);
      EXPECT_LT(k, i);
      EXPECT_NE(j, k);
      EXPECT_EQ(midpointOf(table.gridOf(j), table.gridOf(k)), table.gridOf(i));
    }
  }
}

TEST(SubdivisionTable, LevelsFillConsecutiveRangesAndReadOnlyEarlierLevels) {
  for (int depth = 1; depth <= 7; ++depth) {
    const SubdivisionTable table(depth);
    for (int level = 1; level <= depth; ++level) {
      const int step = 1 << (depth - level);
      const auto begin = std::uint32_t(verticesPerPatch(level - 1)), end = std::uint32_t(verticesPerPatch(level));
      for (std::uint32_t i = begin; i < end; ++i) {
        const GridPoint p = table.gridOf(i);
        EXPECT_TRUE(p.a % step == 0 && p.b % step == 0);
        EXPECT_FALSE(p.a % (2 * step) == 0 && p.b % (2 * step) == 0);
        const auto [j, k] = table.parents(i);
        EXPECT_LT(j, begin);
        EXPECT_LT(k, begin);
      }
    }
  }
}

TEST(SubdivisionTable, ParentPairsAreTheParentsInVertexOrder) {
  const SubdivisionTable table(5);
  const std::vector<std::uint32_t>& pairs = table.parentPairs();
  ASSERT_EQ(pairs.size(), 2 * std::size_t(table.vertexCount()));
  for (std::uint32_t i = 0; i < std::uint32_t(table.vertexCount()); ++i)
    EXPECT_EQ(table.parents(i), (std::array<std::uint32_t, 2>{pairs[2 * i], pairs[2 * i + 1]}));
}

// The pair runs, from the first parent to the second, along the direction of a patch edge as seen from
// that edge's lower-numbered corner: v0 to v1, v0 to v2, or v1 to v2.
TEST(SubdivisionTable, TheFirstParentLiesTowardTheLowerNumberedCorner) {
  const SubdivisionTable table(6);
  const int n = table.segments();
  for (std::uint32_t i = 3; i < std::uint32_t(table.vertexCount()); ++i) {
    const auto [j, k] = table.parents(i);
    const GridPoint p = table.gridOf(i), first = table.gridOf(j), second = table.gridOf(k);
    const int da = second.a - first.a, db = second.b - first.b;
    EXPECT_TRUE((da > 0 && db == 0) || (da == 0 && db > 0) || (da < 0 && db == -da)) << da << ", " << db;
    EXPECT_TRUE(p.b != 0 || first.a < second.a);        // on edge v0 v1: nearer v0
    EXPECT_TRUE(p.a + p.b != n || first.a > second.a);  // on edge v1 v2: nearer v1
    EXPECT_TRUE(p.a != 0 || first.b < second.b);        // on edge v2 v0: nearer v0
  }
}

// Reflecting the grid, (a, b) to (b, a), swaps corners v1 and v2: the edge v0 v1 of one patch becomes edge
// v0 v2 of its mirror, both starting at v0, as for two patches that share an edge and its first corner.
TEST(SubdivisionTable, MirroredPatchesSplitTheEdgeTheyShareFromTheSameOrderedParents) {
  const SubdivisionTable table(6);
  const auto mirror = [](GridPoint p) { return GridPoint{p.b, p.a}; };
  for (int a = 1; a < table.segments(); ++a) {
    const auto [j, k] = table.parents(table.indexOf({a, 0}));
    const auto [mj, mk] = table.parents(table.indexOf({0, a}));
    EXPECT_EQ(mirror(table.gridOf(j)), table.gridOf(mj));
    EXPECT_EQ(mirror(table.gridOf(k)), table.gridOf(mk));
  }
}

}  // namespace
}  // namespace strata::icosahedral
