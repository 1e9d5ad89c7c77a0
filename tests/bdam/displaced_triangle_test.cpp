// geometry.bdam's displaced triangles: corners on the body's sphere, a displacement that puts a point at the distance
// asked anywhere in the triangle and on its edges, to the millimetre and below at any level from a root to
// centimetres; and partners across a hypotenuse (on a face and across a face's edge) that put their shared edge's
// points in the same place.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
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
    for (int k = 0; k <= 8; ++k) {
      const double t = k / 8.0, u = reversed ? 1.0 - t : t;
      const glm::dvec3 fromA = a.flatPoint(1.0 - t, t) + 1000.0 * a.normal(1.0 - t, t);
      const glm::dvec3 fromB = b.flatPoint(1.0 - u, u) + 1000.0 * b.normal(1.0 - u, u);
      EXPECT_LT(glm::length(fromA - fromB), 1e-8) << "m, at " << t << " along the hypotenuse";
    }
  }
}

}  // namespace
}  // namespace strata::bdam
