// geometry.bdam's builder on real heights: EGM96's geoid (proj-data) exaggerated 100 times (+-10 km, Earth's relief)
// on Mars's radius, built from leaves of level 8 (about 330 km a side) to the roots, over the whole body. What the
// paper's construction promises holds on the built data [Cignoni et al. 2003, §3, §5]: errors and spheres nest and are
// shared across every hypotenuse, each node's error bounds its patch's distance from the leaves below it, the patches
// stay a few hundred triangles, and every edge two patches can share holds the same vertices in both, to the bit, on a
// face and across a face's edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <set>

#include "bintree_builder.hpp"
#include "diamonds.hpp"
#include "displaced_triangle.hpp"
#include "patch_codec.hpp"
#include "radial_deviation.hpp"
#include "raster_heights.hpp"
#include "temporary_directory.hpp"

namespace strata::bdam {
namespace {

constexpr double kMars = 3396190.0;  // m
constexpr int kLeafLevel = 8;

const BuiltBintrees& built() {
  static const test::TemporaryDirectory scratch;
  static const BuiltBintrees bintrees = [] {
    const RasterHeights geoid("/usr/share/proj/egm96_15.gtx");
    const HeightsForThread heights = [&geoid] {
      return [sample = geoid.sampler()](const glm::dvec3& d) { return 100.0 * sample(d); };
    };
    return buildBintrees(heights, {kMars, kLeafLevel, 16, 2, scratch.path()}, [](const LevelReport&) {});
  }();
  return bintrees;
}

std::vector<BintreeNode> nodesOf(int level) {
  std::vector<BintreeNode> nodes;
  for (int root = 0; root < kBintreeRoots; ++root)
    for (std::uint64_t path = 0; path < (std::uint64_t(1) << level); ++path) nodes.push_back({root, level, path});
  return nodes;
}

std::vector<glm::dvec3> pointsOf(const BintreeNode& node) {
  const DisplacedTriangle triangle = displacedTriangle(node, kMars);
  std::vector<glm::dvec3> points;
  for (const DisplacedVertex& v : decodePatch(built().stored(node)).vertices) points.push_back(triangle.point(v));
  return points;
}

TEST(BintreeBuilder, ErrorsAndSpheresNestAndAreSharedAcrossHypotenuses) {
  for (int level = 0; level <= kLeafLevel; ++level)
    for (const Diamond& diamond : diamondsOf(level)) {
      const BuiltNode &a = built().at(diamond.halves[0]), &b = built().at(diamond.halves[1]);
      ASSERT_EQ(a.error, b.error);
      ASSERT_EQ(a.sphere.centre, b.sphere.centre);
      ASSERT_EQ(a.sphere.radius, b.sphere.radius);
      for (const BintreeNode& half : diamond.halves)
        for (const glm::dvec3& p : pointsOf(half)) ASSERT_LE(glm::length(p - a.sphere.centre), a.sphere.radius);
      if (level == kLeafLevel) continue;
      for (const BintreeNode& child : diamond.children()) {
        const BuiltNode& c = built().at(child);
        ASSERT_GE(a.error, c.error) << "level " << level;
        ASSERT_LE(glm::length(c.sphere.centre - a.sphere.centre) + c.sphere.radius, a.sphere.radius * (1 + 1e-12));
      }
    }
}

using PositionKey = std::array<std::uint64_t, 3>;

// The positions, as bits, of a node's vertices that `onEdge` picks.
template <typename OnEdge>
std::set<PositionKey> edgeOf(const BintreeNode& node, OnEdge onEdge) {
  const DisplacedTriangle triangle = displacedTriangle(node, kMars);
  std::set<PositionKey> positions;
  for (const DisplacedVertex& v : decodePatch(built().stored(node)).vertices)
    if (onEdge(v)) {
      const glm::dvec3 p = triangle.point(v);
      positions.insert(
          {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y), std::bit_cast<std::uint64_t>(p.z)});
    }
  return positions;
}

// In a bintree cut every shared edge is a node's hypotenuse and its partner's, or a node's hypotenuse and its
// parent's leg (which the parent's neighbours across that leg share): those vertex sets agree, so no cut cracks.
TEST(BintreeBuilder, EveryEdgeTwoPatchesCanShareHoldsTheSameVerticesInBoth) {
  const auto hypotenuse = [](const DisplacedVertex& v) { return v.b1 + v.b2 == kBarycentricSteps; };
  for (int level = 0; level <= kLeafLevel; ++level) {
    for (const Diamond& diamond : diamondsOf(level)) {
      const auto shared = edgeOf(diamond.halves[0], hypotenuse);
      ASSERT_GE(shared.size(), 2u);
      ASSERT_EQ(shared, edgeOf(diamond.halves[1], hypotenuse)) << "level " << level;
    }
    if (level == 0) continue;
    for (const BintreeNode& node : nodesOf(level)) {
      const BintreeNode parent{node.root, level - 1, node.path >> 1};
      const bool second = node.path & 1;  // child 1's hypotenuse is the parent's leg from the apex to corner 2
      const auto leg = [second](const DisplacedVertex& v) { return (second ? v.b1 : v.b2) == 0; };
      ASSERT_EQ(edgeOf(node, hypotenuse), edgeOf(parent, leg)) << "level " << level;
    }
  }
}

// Each node's error bounds its patch's distance from the leaves below it, measured directly; and the patches keep
// a few hundred triangles at every level, as the paper's (it halves a diamond of four).
TEST(BintreeBuilder, ANodesErrorBoundsItsDistanceFromTheLeavesBelowIt) {
  for (int level = 0; level < kLeafLevel; ++level) {
    const std::vector<BintreeNode> nodes = nodesOf(level);
    for (std::size_t n = 0; n < nodes.size(); n += 1 + nodes.size() / 24) {
      const BintreeNode& node = nodes[n];
      const int below = kLeafLevel - level;
      PlanetMesh leaves;
      for (std::uint64_t i = 0; i < (std::uint64_t(1) << below); ++i) {
        const BintreeNode leaf{node.root, kLeafLevel, (node.path << below) | i};
        leaves.append(meshOf(displacedTriangle(leaf, kMars), decodePatch(built().stored(leaf))));
      }
      const DisplacedTriangle triangle = displacedTriangle(node, kMars);
      const DisplacedPatch patch = decodePatch(built().stored(node));
      const double deviation =
          radialDeviation(RadialSurface(triangle, meshOf(triangle, patch)), RadialSurface(triangle, leaves));
      EXPECT_LE(deviation, built().at(node).error) << "level " << level;
      EXPECT_GE(deviation, built().at(node).error / 3) << "level " << level << ": the bound is not tight";
      EXPECT_GE(patch.indices.size() / 3, 128u);
      EXPECT_LE(patch.indices.size() / 3, 400u);
    }
  }
}

}  // namespace
}  // namespace strata::bdam
