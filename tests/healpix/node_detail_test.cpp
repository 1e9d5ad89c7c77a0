// The detail a selection draws: more nodes as the threshold, vertices per pixel, rises (the paper's figure 7
// values; [Westerteiger et al. 2011, §3.2.2]: drawn when area times threshold <= (gridCells + 1)^2), every
// drawn node adequate by the area estimate unless at maxLevel, and the node under an eye 2 m up as fine as
// the estimate's bound demands. The paper's density alone: no pixel error draws a node early
// (node_selection_test.cpp tests that).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "selection_views.hpp"

namespace strata::healpix {
namespace {

TEST(NodeDetail, CountRisesWithTheThreshold) {
  for (const TestView& test : testViews()) {
    std::size_t previous = 0;
    for (const double threshold : {0.005, 0.01, 0.2, 1.0}) {
      const std::size_t count = selectAndReport(test, {.threshold = threshold, .pixelError = 0.0}).size();
      if (previous != 0) {
        EXPECT_GE(count, previous) << test.name << " at " << threshold;
      }
      previous = count;
    }
  }
}

TEST(NodeDetail, DrawnNodesAreAdequate) {
  for (const TestView& test : testViews()) {
    for (const double threshold : {0.005, 0.2, 1.0}) {
      const SelectionSettings settings{.threshold = threshold, .pixelError = 0.0};
      const ShellView shells(test.view(), kEarthRadius, test.heights);
      for (const SelectedNode& node : selectNodes(test.view(), kEarthRadius, test.heights, settings)) {
        if (node.key.level == settings.maxLevel) continue;
        EXPECT_LE(shells.projectedArea(shells.shellOf(node.key), node.key) * threshold, settings.gridVertices())
            << test.name << ": face " << node.key.face << " level " << node.key.level;
      }
    }
  }
}

// Straight down from 2 m: the node under the eye holds a patch of the sphere of area 4 pi R^2 / (12 4^L)
// (HEALPix is equal area) no farther than d = sqrt(h^2 + D^2) with D its diameter, at most 4 sqrt(area) for
// a HEALPix node, facing the eye within acos(h / d); its projection covers at least f^2 area (h / d) / d^2
// pixels (f the focal length in pixels), which the estimate bounds. Drawn means that times the threshold is
// at most (gridCells + 1)^2: the deepest level where this lower bound already exceeds that cannot be drawn,
// nor can any coarser node, which holds it; the bound is the level below.
TEST(NodeDetail, NodeUnderTheEyeIsFine) {
  const TestView test{"2 m down", {45.0, 10.0, 2.0, 0.0, 0.0, 45.0}, {0.0, 0.0}};
  const View view = test.view();
  const SelectionSettings settings{.pixelError = 0.0};
  const double h = test.camera.altitude, f = 0.5 * kHeight / std::tan(0.5 * view.verticalFov);
  int bound = settings.maxLevel;
  for (;; --bound) {
    const double area = 4.0 * std::numbers::pi * kEarthRadius * kEarthRadius / (12.0 * std::ldexp(1.0, 2 * bound));
    const double d = std::hypot(h, 4.0 * std::sqrt(area));
    if (f * f * area * (h / d) / (d * d) * settings.threshold > settings.gridVertices()) break;
  }
  ++bound;
  const FacePoint below = facePoint(view.reference);
  const std::vector<SelectedNode> nodes = selectNodes(view, kEarthRadius, test.heights, settings);
  const auto under = std::ranges::find_if(nodes, [&](const SelectedNode& node) { return node.key.holds(below); });
  ASSERT_NE(under, nodes.end());
  std::printf("node under the eye at 2 m: level %d, bound %d\n", under->key.level, bound);
  EXPECT_GE(under->key.level, bound);
  EXPECT_GE(bound, 24);  // a check on the bound itself: 2^-24 of a face is 39 cm on Earth
}

}  // namespace
}  // namespace strata::healpix
