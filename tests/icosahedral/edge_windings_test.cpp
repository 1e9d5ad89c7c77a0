// The eight edge windings (plugins/geometry-icosahedral/edge_windings.hpp) in grid coordinates, a along x
// and b along y: each covers the patch once with counter-clockwise triangles, a coarse edge skips its odd
// vertices, and the triangle edges along each patch edge are those its neighbour has there.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "edge_windings.hpp"

namespace strata::icosahedral {
namespace {

using GridTriangle = std::array<GridPoint, 3>;
using Segment = std::pair<int, int>;

bool coarse(unsigned coarseEdges, int edge) { return ((coarseEdges >> edge) & 1u) != 0; }

std::vector<GridTriangle> trianglesOf(const SubdivisionTable& table, const EdgeWindings& windings,
                                      unsigned coarseEdges) {
  const IndexRange range = windings.range(coarseEdges);
  std::vector<GridTriangle> triangles;
  for (std::uint32_t i = range.first; i < range.first + range.count; i += 3) {
    const std::vector<std::uint32_t>& indices = windings.indices();
    triangles.push_back({table.gridOf(indices[i]), table.gridOf(indices[i + 1]), table.gridOf(indices[i + 2])});
  }
  return triangles;
}

int twiceArea(const GridTriangle& t) {
  return (t[1].a - t[0].a) * (t[2].b - t[0].b) - (t[1].b - t[0].b) * (t[2].a - t[0].a);
}

// Where a grid point lies along patch edge `edge`, counted from the edge's first corner, if it lies on it.
std::optional<int> alongEdge(GridPoint p, int edge, int n) {
  if (edge == 0 && p.b == 0) return p.a;
  if (edge == 1 && p.a + p.b == n) return p.b;
  if (edge == 2 && p.a == 0) return n - p.b;
  return std::nullopt;
}

// The triangle edges that lie on patch edge `edge`, as (from, to) along it in the triangles' own order.
std::vector<Segment> segmentsOnEdge(const std::vector<GridTriangle>& triangles, int edge, int n) {
  std::vector<Segment> segments;
  for (const GridTriangle& t : triangles)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::optional<int> from = alongEdge(t[c], edge, n), to = alongEdge(t[(c + 1) % 3], edge, n);
      if (from && to) segments.emplace_back(*from, *to);
    }
  std::ranges::sort(segments);
  return segments;
}

class EveryWinding : public testing::TestWithParam<int> {
 protected:
  SubdivisionTable table{GetParam()};
  EdgeWindings windings{table};
  int n = table.segments();
};

TEST(EdgeWindings, FullResolutionHasFourToTheDepthTriangles) {
  for (int depth = 0; depth <= 7; ++depth) {
    const SubdivisionTable table(depth);
    EXPECT_EQ(EdgeWindings(table).range(0).count, 3u << (2 * depth)) << "depth " << depth;
  }
}

TEST(EdgeWindings, AtDepthZeroEveryWindingIsThePatchsTriangle) {
  const SubdivisionTable table(0);
  const EdgeWindings windings(table);
  for (unsigned coarseEdges = 0; coarseEdges < kEdgeWindingCount; ++coarseEdges) {
    const IndexRange range = windings.range(coarseEdges);
    ASSERT_EQ(range.count, 3u);
    const std::vector<std::uint32_t> triangle(windings.indices().begin() + range.first,
                                              windings.indices().begin() + range.first + 3);
    EXPECT_EQ(triangle, (std::vector<std::uint32_t>{0, 1, 2}));
  }
}

TEST_P(EveryWinding, RangesFollowOneAnotherThroughTheElementArray) {
  std::uint32_t next = 0;
  for (unsigned coarseEdges = 0; coarseEdges < kEdgeWindingCount; ++coarseEdges) {
    EXPECT_EQ(windings.range(coarseEdges).first, next);
    EXPECT_EQ(windings.range(coarseEdges).count % 3, 0u);
    next += windings.range(coarseEdges).count;
  }
  EXPECT_EQ(next, windings.indices().size());
  const auto vertexCount = std::uint32_t(table.vertexCount());
  EXPECT_TRUE(std::ranges::all_of(windings.indices(), [&](std::uint32_t i) { return i < vertexCount; }));
}

// Counter-clockwise triangles of positive area whose areas sum to the patch's, and whose directed edges
// each occur once, inside the patch always met by the reverse edge of a neighbour and on its boundary
// never: together these make a triangulation of the whole patch without overlaps.
TEST_P(EveryWinding, CoversThePatchOnceWithCounterClockwiseTriangles) {
  for (unsigned coarseEdges = 0; coarseEdges < kEdgeWindingCount; ++coarseEdges) {
    SCOPED_TRACE(testing::Message() << "coarse edges " << coarseEdges);
    int area = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const GridTriangle& t : trianglesOf(table, windings, coarseEdges)) {
      EXPECT_GT(twiceArea(t), 0);
      area += twiceArea(t);
      for (std::size_t c = 0; c < 3; ++c) ++directed[{table.indexOf(t[c]), table.indexOf(t[(c + 1) % 3])}];
    }
    EXPECT_EQ(area, n * n);
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      const GridPoint p = table.gridOf(edge.first), q = table.gridOf(edge.second);
      const bool onBoundary = (p.b == 0 && q.b == 0) || (p.a + p.b == n && q.a + q.b == n) || (p.a == 0 && q.a == 0);
      EXPECT_EQ(directed.contains({edge.second, edge.first}), !onBoundary);
    }
  }
}

TEST_P(EveryWinding, CoarseEdgesNeverReferenceTheirOddVertices) {
  for (unsigned coarseEdges = 1; coarseEdges < kEdgeWindingCount; ++coarseEdges)
    for (const GridTriangle& t : trianglesOf(table, windings, coarseEdges))
      for (GridPoint p : t)
        for (int edge = 0; edge < 3; ++edge) {
          const std::optional<int> along = alongEdge(p, edge, n);
          EXPECT_FALSE(coarse(coarseEdges, edge) && along && *along % 2 != 0)
              << "coarse edges " << coarseEdges << " use (" << p.a << ", " << p.b << ")";
        }
}

// Along each patch edge the triangle edges run counter-clockwise (from the edge's first corner to its
// second) between consecutive vertices the neighbour has: every other one across a coarse edge, every
// one across an edge of the same depth. So every such vertex is used, and no crack can open.
TEST_P(EveryWinding, PatchEdgesAreSplitAsTheNeighbourSplitsThem) {
  for (unsigned coarseEdges = 0; coarseEdges < kEdgeWindingCount; ++coarseEdges)
    for (int edge = 0; edge < 3; ++edge) {
      const int step = coarse(coarseEdges, edge) ? 2 : 1;
      std::vector<Segment> expected;
      for (int from = 0; from < n; from += step) expected.emplace_back(from, from + step);
      EXPECT_EQ(segmentsOnEdge(trianglesOf(table, windings, coarseEdges), edge, n), expected)
          << "coarse edges " << coarseEdges << ", edge " << edge;
    }
}

std::string depthName(const testing::TestParamInfo<int>& depth) { return "depth" + std::to_string(depth.param); }
INSTANTIATE_TEST_SUITE_P(Depths, EveryWinding, testing::Range(1, 7), depthName);

}  // namespace
}  // namespace strata::icosahedral
