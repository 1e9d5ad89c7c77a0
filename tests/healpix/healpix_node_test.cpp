// The node geometry node_selection relies on: the cone and box margins hold dense samples of the node, and
// acrossEdge lands in the node sharing the edge, across base-face boundaries too.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "healpix_node.hpp"
#include "selection_views.hpp"

namespace strata::healpix {
namespace {

// Every node of levels 0 to 3, and 3000 random nodes of levels 4 to 26.
std::vector<NodeKey> probeNodes() {
  std::vector<NodeKey> nodes;
  for (int face = 0; face < 12; ++face) {
    for (int level = 0; level <= 3; ++level) {
      for (std::int64_t ix = 0; ix < (1 << level); ++ix) {
        for (std::int64_t iy = 0; iy < (1 << level); ++iy) nodes.push_back({face, level, ix, iy});
      }
    }
  }
  std::mt19937_64 random(6);
  for (int i = 0; i < 3000; ++i) {
    const int level = 4 + int(random() % 23);
    const std::int64_t n = std::int64_t{1} << level;
    nodes.push_back({int(random() % 12), level, std::int64_t(random() % std::uint64_t(n)),
                     std::int64_t(random() % std::uint64_t(n))});
  }
  return nodes;
}

// A 33 x 33 lattice over the node, boundary included: 32 steps per edge, beyond the selection's 2.
std::vector<glm::dvec3> denseSamples(const NodeKey& key) {
  std::vector<glm::dvec3> samples;
  for (int i = 0; i <= 32; ++i) {
    for (int j = 0; j <= 32; ++j) samples.push_back(unitVector(key.at(i / 32.0, j / 32.0)));
  }
  return samples;
}

TEST(HealpixNode, ConeHoldsTheNode) {
  double tightest = 1e9;  // the least margin left, as a fraction of the cone's half angle
  for (const NodeKey& key : probeNodes()) {
    const NodeCone cone = coneOf(key);
    for (const glm::dvec3& u : denseSamples(key)) {
      const double angle = angleBetween(cone.centre, u);
      tightest = std::min(tightest, 1.0 - angle / cone.angle);
      ASSERT_LE(angle, cone.angle) << "face " << key.face << " level " << key.level;
    }
  }
  std::printf("cone: least margin left %.3f of the half angle\n", tightest);
}

TEST(HealpixNode, BoxHoldsTheShell) {
  const TestView test = testViews()[1];
  const ShellView shells(test.view(), kEarthRadius, test.heights);
  for (const NodeKey& key : probeNodes()) {
    const NodeShell shell = shells.shellOf(key);
    // The box's edges from corner 0 run along bits 1, 2 and 4 of the corner index.
    for (const glm::dvec3& u : denseSamples(key)) {
      for (const double r : {shell.innerRadius, shell.outerRadius}) {
        for (const int bit : {1, 2, 4}) {
          const glm::dvec3 edge = shell.box[std::size_t(bit)] - shell.box[0];
          const double length = glm::length(edge), t = glm::dot(r * u - shell.box[0], edge / length);
          const double tolerance = 1e-6;  // m; rounding at planet scale is about 1e-9 m
          ASSERT_GE(t, -tolerance) << "face " << key.face << " level " << key.level << " axis " << bit;
          ASSERT_LE(t, length + tolerance) << "face " << key.face << " level " << key.level << " axis " << bit;
        }
      }
    }
  }
}

TEST(HealpixNode, AcrossEdgeLandsInTheNodeSharingTheEdge) {
  int acrossFaces = 0;
  for (const NodeKey& key : probeNodes()) {
    for (int edge = 0; edge < 4; ++edge) {
      const FacePoint beyond = acrossEdge(key, edge);
      ASSERT_FALSE(key.holds(beyond));
      const NodeKey neighbour = nodeAt(beyond, key.level);
      acrossFaces += neighbour.face != key.face;
      // The neighbour's corners include both ends of the edge, on the sphere.
      for (const int end : {edge, (edge + 1) % 4}) {
        const glm::dvec3 u = unitVector(key.corner(end));
        double nearest = 1.0;
        for (int c = 0; c < 4; ++c) nearest = std::min(nearest, glm::length(unitVector(neighbour.corner(c)) - u));
        ASSERT_LT(nearest, 1e-13) << "face " << key.face << " level " << key.level << " edge " << edge;
      }
    }
  }
  EXPECT_GT(acrossFaces, 100);
}

}  // namespace
}  // namespace strata::healpix
