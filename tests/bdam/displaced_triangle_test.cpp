// geometry.bdam's displaced triangles: corners on the body's sphere, a displacement that puts a point at the distance
// asked anywhere in the triangle and on its edges, to the millimetre and below at any level from a root to
// centimetres; and partners across a hypotenuse (on a face and across a face's edge) that put their shared edge's
// points in the same place, to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "cube_bintree.hpp"
#include "displaced_triangle.hpp"

namespace strata::bdam {
namespace {

constexpr double kMars = 3396190.0;  // m

// The node of `level` reached by taking child (level + seed) % 2 at every step from root `root`.
BintreeNode descend(int root, int level, int seed) {
  BintreeNode node{root, 0, 0};
  for (int l = 0; l < level; ++l) node = children(node)[std::size_t((l + seed) % 2)];
  return node;
}

TEST(DisplacedTriangle, CornersLieOnTheSphere) {
  for (int root = 0; root < kBintreeRoots; ++root) {
    const DisplacedTriangle triangle = displacedTriangle(descend(root, 7, root), kMars);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(glm::length(triangle.corners[std::size_t(i)]), kMars, 1e-6);
      EXPECT_NEAR(glm::length(triangle.normals[std::size_t(i)]), 1.0, 1e-15);
    }
    EXPECT_EQ(triangle.point({0, 0, 0}), triangle.corners[0]);
  }
}

TEST(DisplacedTriangle, ADisplacementPutsThePointAtTheDistanceAsked) {
  for (const int level : {0, 10, 30, 54}) {  // half a face (5,300 km a side) down to corners 4 cm apart
    const DisplacedTriangle triangle = displacedTriangle(descend(5, level, 1), kMars);
    for (const double height : {-8200.0, 0.0, 0.01, 21229.0})
      for (const glm::dvec2 b : {glm::dvec2(1.0 / 3.0, 1.0 / 3.0), glm::dvec2(0.5, 0.5), glm::dvec2(0.0, 0.7),
                                 glm::dvec2(0.9, 0.05), glm::dvec2(1.0, 0.0)}) {
        const double h = triangle.displacementTo(b.x, b.y, kMars + height);
        const double reached = glm::length(triangle.flatPoint(b.x, b.y) + h * triangle.normal(b.x, b.y));
        EXPECT_NEAR(reached, kMars + height, 1e-6) << "level " << level << ", " << b.x << ", " << b.y;
      }
  }
}

// Each node at `level` of every root, with its hypotenuse's ends as a key; partners share one.
TEST(DisplacedTriangle, PartnersAcrossAHypotenusePutItsPointsInOnePlace) {
  std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, std::vector<BintreeNode>>
      partners;
  std::vector<BintreeNode> nodes;
  for (int root = 0; root < kBintreeRoots; ++root) nodes.push_back({root, 0, 0});
  for (int l = 0; l < 6; ++l) {
    std::vector<BintreeNode> finer;
    for (const BintreeNode& node : nodes)
      for (const BintreeNode& child : children(node)) finer.push_back(child);
    nodes.swap(finer);
  }
  for (const BintreeNode& node : nodes) {
    const DisplacedTriangle t = displacedTriangle(node, kMars);
    const auto key = [](const glm::dvec3& v) { return std::tuple(v.x, v.y, v.z); };
    partners[std::minmax(key(t.corners[1]), key(t.corners[2]))].push_back(node);
  }
  for (const auto& [ends, pair] : partners) {
    ASSERT_EQ(pair.size(), 2u);
    const DisplacedTriangle a = displacedTriangle(pair[0], kMars), b = displacedTriangle(pair[1], kMars);
    const bool reversed = a.corners[1] == b.corners[2];  // the partner walks the hypotenuse the other way
    for (int k = 0; k <= 8; ++k) {  // lattice points along it, a kilometre up: the same bits from either side
      const auto t = std::uint16_t(k * kBarycentricSteps / 8), u = reversed ? std::uint16_t(kBarycentricSteps - t) : t;
      const DisplacedVertex onA{std::uint16_t(kBarycentricSteps - t), t, 100000};
      const DisplacedVertex onB{std::uint16_t(kBarycentricSteps - u), u, 100000};
      EXPECT_EQ(a.point(onA), b.point(onB)) << "at " << t << " steps along the hypotenuse";
    }
  }
}

// The builder re-stores each kept vertex in its parent's triangle: a point of the lattice comes back as itself, inside
// and on each edge (from the edge's corners alone), from a root to triangles of metres, kilometres up and down.
TEST(DisplacedTriangle, AStoredVertexIsFoundAgainFromItsPoint) {
  std::mt19937 random(31);
  std::uniform_int_distribution<int> step(1, kBarycentricSteps - 1), centimetres(-900000, 900000);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (const int level : {0, 7, 20, 36})
    for (int n = 0; n < 200; ++n) {
      const glm::dvec3 place(coordinate(random), coordinate(random), coordinate(random));
      const BintreeNode node = nodeContaining(glm::normalize(place), level);
      const DisplacedTriangle triangle = displacedTriangle(node, kMars);
      const auto b2 = std::uint16_t(step(random)), b1 = std::uint16_t(step(random) % (kBarycentricSteps - b2));
      const std::int32_t h = centimetres(random) / (level > 20 ? 1000 : 1);
      const std::array<std::pair<DisplacedVertex, int>, 4> vertices = {
          {{{std::max<std::uint16_t>(b1, 1), b2, h}, -1},
           {{std::uint16_t(kBarycentricSteps - b2), b2, h}, 0},
           {{0, b2, h}, 1},
           {{b1, 0, h}, 2}}};
      for (const auto& [vertex, edge] : vertices)
        ASSERT_EQ(triangle.vertexAt(triangle.point(vertex), edge), vertex) << "level " << level << ", edge " << edge;
    }
}

}  // namespace
}  // namespace strata::bdam
