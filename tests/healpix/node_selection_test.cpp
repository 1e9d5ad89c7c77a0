// geometry.healpix's node selection covers what a view sees exactly once: the selected nodes never overlap,
// and every point of the sphere of the lowest height that a pixel's ray meets, in front of the near plane,
// lies in exactly one of them. From every view of selection_views.hpp, which prints counts and times.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <unordered_set>
#include <vector>

#include <glm/geometric.hpp>

#include "selection_views.hpp"

namespace strata::healpix {
namespace {

// Where the ray from the eye through pixel (px, py) (centres at + 0.5) meets the sphere of `radius` first,
// if it does, in front of the near plane.
std::optional<glm::dvec3> surfaceAt(const View& view, double px, double py, double radius) {
  const double ty = std::tan(0.5 * view.verticalFov), tx = ty * double(view.width) / double(view.height);
  const glm::dvec3 eyeRay((2.0 * px / view.width - 1.0) * tx, (1.0 - 2.0 * py / view.height) * ty, -1.0);
  const glm::dvec3 d = glm::normalize(glm::transpose(view.planetToEye) * eyeRay);
  const double distance = glm::length(view.eye), b = glm::dot(view.eye, d);
  const double c = (distance - radius) * (distance + radius), discriminant = b * b - c;
  if (discriminant < 0.0 || b >= 0.0) return std::nullopt;
  const double t = c / (-b + std::sqrt(discriminant));  // the nearer root, without cancellation
  if (t / glm::length(eyeRay) < view.near) return std::nullopt;
  return view.eye + t * d;
}

TEST(NodeSelection, NodesNeverOverlap) {
  for (const TestView& test : testViews()) {
    const std::vector<SelectedNode> nodes = selectAndReport(test, {});
    std::unordered_set<NodeKey, NodeKeyHash> keys;
    for (const SelectedNode& node : nodes) ASSERT_TRUE(keys.insert(node.key).second) << test.name;
    for (const SelectedNode& node : nodes) {
      for (NodeKey above = node.key; above.level > 0;) {
        above = above.parent();
        ASSERT_FALSE(keys.contains(above)) << test.name << ": a node and its ancestor at level " << above.level;
      }
    }
  }
}

TEST(NodeSelection, EveryVisiblePointLiesInExactlyOneNode) {
  constexpr int kColumns = 193, kRows = 109;  // every 10th pixel, the borders' centres included
  for (const TestView& test : testViews()) {
    const View view = test.view();
    const std::vector<SelectedNode> nodes = selectNodes(view, kEarthRadius, test.heights, {});
    int seen = 0;
    for (int i = 0; i < kColumns; ++i) {
      for (int j = 0; j < kRows; ++j) {
        const double px = 0.5 + (kWidth - 1.0) * i / (kColumns - 1), py = 0.5 + (kHeight - 1.0) * j / (kRows - 1);
        const auto point = surfaceAt(view, px, py, kEarthRadius + test.heights.lowest);
        if (!point) continue;
        ++seen;
        const glm::dvec3 u = glm::normalize(*point);
        const FacePoint place = facePoint({std::atan2(u.y, u.x), std::atan2(u.z, std::hypot(u.x, u.y))});
        int holding = 0;
        for (const SelectedNode& node : nodes) holding += node.key.holds(place);
        ASSERT_EQ(holding, 1) << test.name << " at pixel " << px << ", " << py;
      }
    }
    std::printf("%-36s %5d of %d rays meet the surface\n", test.name.c_str(), seen, kColumns * kRows);
    EXPECT_GT(seen, 100) << test.name;
  }
}

// Level of detail by screen-space error (SelectionSettings::pixelError): the bare sphere's error is its chords'
// sagitta, under a pixel for nodes far coarser than the paper's density asks, so from orbit and from 2 m it takes a
// small share of the nodes the threshold alone draws; relief known only as the whole range (+-12 km) shows as error,
// and takes more. Every node drawn by its error shows no more than the pixel error.
TEST(NodeSelection, TheBareSphereTakesFewNodesAndReliefMore) {
  const SelectionSettings byError, byThreshold{.pixelError = 0.0};
  for (const Camera& camera : {Camera{10.0, 20.0, 2.0e7, 0.0, 0.0, 36.0}, Camera{137.4, -4.6, 2.0, 30.0, 60.0, 36.0}}) {
    const View view = makeView(Body{"Earth", kEarthRadius}, camera, kWidth, kHeight);
    const std::size_t bare = selectNodes(view, kEarthRadius, {0.0, 0.0}, byError).size();
    const std::size_t dense = selectNodes(view, kEarthRadius, {0.0, 0.0}, byThreshold).size();
    const HeightRange relief{-12000.0, 12000.0};
    const View overRelief = makeView(Body{"Earth", kEarthRadius}, camera, kWidth, kHeight, relief);
    const std::size_t rough = selectNodes(overRelief, kEarthRadius, relief, byError).size();
    std::printf("%.0f m up: %zu nodes by the error on the bare sphere, %zu by the threshold alone, %zu over relief\n",
                camera.altitude, bare, dense, rough);
    EXPECT_LT(4 * bare, dense);
    EXPECT_GT(rough, bare);
    const ShellView shells(view, kEarthRadius, {0.0, 0.0});
    for (const SelectedNode& node : selectNodes(view, kEarthRadius, {0.0, 0.0}, byError)) {
      const NodeShell shell = shells.shellOf(node.key);
      if (shells.projectedArea(shell, node.key) * byError.threshold <= byError.gridVertices()) continue;
      EXPECT_LE(shells.screenError(shell, node.key, byError.gridCells), byError.pixelError);
    }
  }
}

// Per-node heights (a HEALPix pyramid's page ranges, HealpixFaceLayer::faceNodeValues) in place of one global range: 5
// km above ground whose heights reach +-240 km somewhere (procedural.yaml's relief exaggerated 20 times) but lie within
// +-2 km here, the shells near the eye shrink from columns 480 km tall to 4 km, and far fewer nodes are drawn; every
// ray that meets the ground still lands in exactly one node.
TEST(NodeSelection, PerNodeHeightsRefineOnlyWhatTheViewNeeds) {
  const HeightRange global{-240000.0, 240000.0}, local{-2000.0, 2000.0};
  const View view = makeView(Body{"Earth", kEarthRadius}, {20.0, 30.0, 5000.0, 60.0, 70.0, 45.0}, kWidth, kHeight);
  const std::vector<SelectedNode> coarse = selectNodes(view, kEarthRadius, global, {});
  const NodeHeights known = [&](const NodeKey&, const NodeCone&) -> std::optional<RegionalHeights> {
    return RegionalHeights{local};
  };
  const std::vector<SelectedNode> fine = selectNodes(view, kEarthRadius, global, {}, known);
  std::printf("5 km up, heights +-240 km: %zu nodes; known to lie within +-2 km: %zu nodes\n", coarse.size(),
              fine.size());
  EXPECT_LT(fine.size() * 4, coarse.size());
  const NodeHeights unknown = [](const NodeKey&, const NodeCone&) -> std::optional<RegionalHeights> {
    return std::nullopt;
  };
  EXPECT_EQ(selectNodes(view, kEarthRadius, global, {}, unknown).size(), coarse.size());
  int seen = 0;
  for (int i = 0; i < 97; ++i)
    for (int j = 0; j < 55; ++j) {
      const auto point = surfaceAt(view, 0.5 + (kWidth - 1.0) * i / 96.0, 0.5 + (kHeight - 1.0) * j / 54.0,
                                   kEarthRadius + local.lowest);
      if (!point) continue;
      ++seen;
      const glm::dvec3 u = glm::normalize(*point);
      const FacePoint place = facePoint({std::atan2(u.y, u.x), std::atan2(u.z, std::hypot(u.x, u.y))});
      int holding = 0;
      for (const SelectedNode& node : fine) holding += node.key.holds(place);
      ASSERT_EQ(holding, 1) << "ray " << i << ", " << j;
    }
  EXPECT_GT(seen, 1000);
}

}  // namespace
}  // namespace strata::healpix
