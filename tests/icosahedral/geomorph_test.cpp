// Geomorphing (issue 4, docs/geometry.md): the drawn surface moves continuously as the eye does, so a
// fly-in shows no pops. The compute pass subdivides a settled tree's patches over relief of kilometres for
// an eye descending in steps of a thousandth of its height; every drawn vertex must move, between steps,
// by a small share of its distance, where a vertex that popped from its parents' midpoint to its own point
// would jump by its share of the relief. And a patch whose split is just being made draws its finest
// vertices at their parents' midpoints, so that the split itself changes nothing on screen. Both hold
// whether the tree and the vertices measure on the sphere or, where each patch's heights are known, on the
// terrain (the tree to each patch's shell, the vertices at their displaced points).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <strata/body.hpp>

#include "gpu_patches.hpp"

namespace strata::icosahedral {
namespace {

constexpr double kEarth = test::GpuPatches::kRadius;
constexpr int kDepth = test::GpuPatches::kDepth;
constexpr double kRelief = 3000.0;  // m: the test terrain's amplitude
// Relief in waves 60 km long east-west and north-south: some tens of vertices across at the levels an
// eye 30 km up draws, so that every level's vertices sit off their parents' midpoints by up to hundreds of
// metres.
const char* const kTerrain = R"(
vec4 testTerrain(SurfacePoint p) {
  float k = 6371000.0 / 60000.0 * 6.2831853;
  return vec4(3000.0 * sin(k * p.fromReference.x) * cos(k * p.fromReference.y), 0.0, 0.0, 1.0);
}
)";

// Measured on the terrain (true) or on the sphere.
class Geomorphing : public ::testing::TestWithParam<bool> {
 protected:
  // The tree, told each patch's heights on the terrain: here the relief's whole range, which bounds them.
  PatchTree tree() const {
    if (!GetParam()) return PatchTree(kEarth, {-kRelief, kRelief});
    return PatchTree(kEarth, {-kRelief, kRelief}, {}, [](const SphericalTriangle&) {
      return RegionalHeights{{-kRelief, kRelief}};
    });
  }
  // The planet-fixed drawn points (x, y, z) and morphs (w) of the patches seen from `view`.
  std::vector<glm::dvec4> drawnPoints(test::GpuPatches& gpu, const std::vector<Patch>& patches, const View& view,
                                      double splitDistanceUnit) const;
};

std::vector<glm::dvec4> Geomorphing::drawnPoints(test::GpuPatches& gpu, const std::vector<Patch>& patches,
                                                 const View& view, double splitDistanceUnit) const {
  std::vector<glm::dvec4> points;
  for (const PatchBuffers::Vertex& vertex : gpu.subdivide(patches, view, splitDistanceUnit, GetParam()).vertices)
    points.emplace_back(glm::dvec3(vertex.drawn) + view.eye, vertex.drawn.w);
  return points;
}

View viewFrom(double altitude) {
  return makeView(Body{"Earth", kEarth}, {.lon = 10, .lat = 45, .altitude = altitude, .tilt = 60}, 1280, 720);
}

// The largest move of a drawn vertex between steps, over its distance from the eye, must stay under 2e-5:
// a thirtieth of a pixel of a 1280-pixel, 45-degree view (6e-4 rad), where vertices drawn without
// morphing (a morph band of 1e-6) jumped by up to 4.7e-4, most of a pixel, at every step. The detail scale
// differs across the view (DetailField: the near patches ask for more), and vertices morph by the scale where
// they lie.
TEST_P(Geomorphing, DrawnVerticesMoveContinuouslyAsTheEyeDescends) {
  test::GpuPatches gpu("testTerrain", kTerrain);
  PatchTree tree = this->tree();
  const std::vector<ViewVolume> views{ViewVolume(viewFrom(3e4))};
  tree.settle(views);
  const std::vector<Patch> patches = tree.visiblePatches();
  std::vector<glm::dvec4> previous = drawnPoints(gpu, patches, viewFrom(3e4), tree.splitDistanceUnit());
  double largest = 0.0;
  int morphing = 0;
  for (int step = 1; step <= 40; ++step) {
    const View view = viewFrom(3e4 * std::pow(0.999, step));
    const std::vector<glm::dvec4> next = drawnPoints(gpu, patches, view, tree.splitDistanceUnit());
    for (std::size_t i = 0; i < next.size(); ++i) {
      const double distance = glm::length(glm::dvec3(next[i]) - view.eye);
      largest = std::max(largest, glm::length(glm::dvec3(next[i] - previous[i])) / distance);
      morphing += int(next[i].w > 0.0 && next[i].w < 1.0);
    }
    previous = next;
  }
  EXPECT_LT(largest, 2e-5);
  EXPECT_GT(morphing, 10000) << "vertex-steps between their parents' midpoint and their own point";
  const std::vector<double>& field = tree.detailField().values();
  EXPECT_GT(std::ranges::max(field), 2.0 * std::ranges::min(field)) << "the detail scale varies across the view";
}

// The four children of every visible leaf: a leaf lies at or beyond its split distance, so the children's
// finest vertices, which its split would bring in, must be drawn fully at their parents' midpoint.
TEST_P(Geomorphing, ASplitBeingMadeDrawsTheNewVerticesAtTheirParentsMidpoints) {
  test::GpuPatches gpu("testTerrain", kTerrain);
  PatchTree tree = this->tree();
  const View view = viewFrom(3e4);
  const std::vector<ViewVolume> views{ViewVolume(view)};
  tree.settle(views);
  std::vector<Patch> children;
  for (const Patch& leaf : tree.visiblePatches()) {
    ASSERT_GE(leaf.level, DetailField::kLevel) << "its children's detail scales are their corners' means";
    const auto& [a, b, c] = leaf.corners;
    const glm::dvec3 ab = greatCircleMidpoint(a, b), bc = greatCircleMidpoint(b, c), ca = greatCircleMidpoint(c, a);
    const auto& [da, db, dc] = std::array<float, 3>{leaf.details[0], leaf.details[1], leaf.details[2]};
    const float dab = 0.5f * (da + db), dbc = 0.5f * (db + dc), dca = 0.5f * (dc + da);
    for (const auto& [corners, details] : {std::pair{SphericalTriangle{a, ab, ca}, std::array{da, dab, dca}},
                                           std::pair{SphericalTriangle{ab, b, bc}, std::array{dab, db, dbc}},
                                           std::pair{SphericalTriangle{ca, bc, c}, std::array{dca, dbc, dc}},
                                           std::pair{SphericalTriangle{ab, bc, ca}, std::array{dab, dbc, dca}}}) {
      children.push_back({corners, leaf.level + 1, 0});
      std::ranges::copy(details, children.back().details.begin());
    }
  }
  const std::vector<glm::dvec4> drawn = drawnPoints(gpu, children, view, tree.splitDistanceUnit());
  const SubdivisionTable& table = gpu.table();
  double largestMorph = 0.0;
  for (std::size_t patch = 0; patch < children.size(); ++patch)
    for (int v = verticesPerPatch(kDepth - 1); v < table.vertexCount(); ++v)  // breadth first: the finest last
      largestMorph = std::max(largestMorph, drawn[patch * std::size_t(table.vertexCount()) + std::size_t(v)].w);
  EXPECT_GT(children.size(), 400u);
  EXPECT_LT(largestMorph, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(MeasuredOn, Geomorphing, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& measured) {
                           return measured.param ? "Terrain" : "Sphere";
                         });

}  // namespace
}  // namespace strata::icosahedral
