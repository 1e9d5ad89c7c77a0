// geometry.clipmap's static hemisphere: the paper's triangle counts, unit vectors whose rings halve level by level,
// no T-junction between levels, a closed surface from the outer ring in, and seams beyond the poles that no triangle
// crosses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "hemisphere_rings.hpp"

namespace strata::clipmap {
namespace {

TEST(HemisphereRings, ALevelHoldsThePapersTwentyThousandTriangles) {
  // [Clasen & Hege 2006, §3.4, §5.2]: 512 steps, 20 rings a level; 16 levels about 330,000 triangles.
  const HemisphereRings mesh = buildHemisphereRings({.steps = 512, .ringsPerLevel = 20, .levels = 24});
  ASSERT_EQ(mesh.levels.size(), 24u);
  for (const IndexRange& level : mesh.levels) EXPECT_EQ(level.count / 3, 20480u);
  for (const IndexRange& cap : mesh.caps) EXPECT_EQ(cap.count / 3, 512u);
  EXPECT_EQ(16 * 20480, 327680);
  for (std::size_t i = 1; i < mesh.levels.size(); ++i)
    EXPECT_EQ(mesh.levels[i].first, mesh.levels[i - 1].first + mesh.levels[i - 1].count)
        << "coarsest first, contiguous";
}

TEST(HemisphereRings, VerticesAreUnitVectorsOnRingsThatHalveEachLevel) {
  const RingSettings settings{.steps = 64, .ringsPerLevel = 5, .levels = 40};
  const HemisphereRings mesh = buildHemisphereRings(settings);
  for (const HemisphereVertex& v : mesh.vertices) {
    const double up = 1.0 + double(v.upMinusOne), theta = std::abs(double(v.colatitude));
    EXPECT_NEAR(double(v.east) * v.east + double(v.north) * v.north + up * up, 1.0, 1e-6);
    EXPECT_NEAR(std::hypot(double(v.east), double(v.north)), std::sin(theta), 1e-7 * std::max(theta, 1e-30) + 1e-7);
    const double dip = -2.0 * std::pow(std::sin(0.5 * theta), 2);  // cos(theta) - 1 without its cancellation
    // Float keeps cos(theta) - 1 to its last digits; theta read back as float moves it by twice its rounding.
    EXPECT_NEAR(double(v.upMinusOne), dip, 3e-7 * -dip);
  }
  for (int level = 0; level <= settings.levels; ++level)
    EXPECT_DOUBLE_EQ(ringColatitude(level * settings.ringsPerLevel, settings.ringsPerLevel),
                     std::numbers::pi * std::exp2(-level));
}

// A vertex's place on the mesh, the same for both copies of a seam's column: its ring's colatitude and its column
// (0 to steps - 1); the nadir is (0, 0).
std::pair<float, int> placeOf(const HemisphereVertex& v, int steps) {
  if (v.colatitude == 0.0f) return {0.0f, 0};
  double azimuth = std::atan2(double(v.east), double(v.north));
  if (azimuth < 0.0) azimuth += 2.0 * std::numbers::pi;
  return {std::abs(v.colatitude), int(std::lround(azimuth * steps / (2.0 * std::numbers::pi))) % steps};
}

using Edge = std::pair<std::pair<float, int>, std::pair<float, int>>;

// How many of the triangles in `ranges` hold each edge, edges named by their ends' places.
std::map<Edge, int> edgeUses(const HemisphereRings& mesh, std::initializer_list<IndexRange> ranges) {
  std::map<Edge, int> uses;
  for (const IndexRange& range : ranges)
    for (std::uint32_t t = range.first; t < range.first + range.count; t += 3)
      for (int e = 0; e < 3; ++e) {
        auto a = placeOf(mesh.vertices[mesh.indices[t + e]], mesh.settings.steps);
        auto b = placeOf(mesh.vertices[mesh.indices[t + (e + 1) % 3]], mesh.settings.steps);
        if (b < a) std::swap(a, b);
        ++uses[{a, b}];
      }
  return uses;
}

TEST(HemisphereRings, LevelsAndTheCapCloseTheSurfaceWithoutTJunctions) {
  // Every edge of levels 3 to 7 and level 7's cap is held by two triangles, but for the outer ring's, held by one:
  // a T-junction or a crack would leave an inner edge held once.
  const RingSettings settings{.steps = 32, .ringsPerLevel = 4, .levels = 10};
  const HemisphereRings mesh = buildHemisphereRings(settings);
  const std::map<Edge, int> uses =
      edgeUses(mesh, {mesh.levels[3], mesh.levels[4], mesh.levels[5], mesh.levels[6], mesh.levels[7], mesh.caps[7]});
  const float outer = float(ringColatitude(3 * settings.ringsPerLevel, settings.ringsPerLevel));
  int outerEdges = 0;
  for (const auto& [edge, count] : uses) {
    const bool onOuterRing = edge.first.first == outer && edge.second.first == outer;
    outerEdges += onOuterRing;
    EXPECT_EQ(count, onOuterRing ? 1 : 2)
        << edge.first.first << "," << edge.first.second << " - " << edge.second.first << "," << edge.second.second;
  }
  EXPECT_EQ(outerEdges, settings.steps);
}

TEST(HemisphereRings, NoTriangleCrossesTheSeamsDueNorthAndDueSouth) {
  const HemisphereRings mesh = buildHemisphereRings({.steps = 64, .ringsPerLevel = 3, .levels = 6});
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    std::set<int> halves;
    for (int e = 0; e < 3; ++e) {
      const float c = mesh.vertices[mesh.indices[t + e]].colatitude;
      if (c != 0.0f) halves.insert(c < 0.0f ? -1 : 1);
    }
    EXPECT_EQ(halves.size(), 1u) << "triangle " << t / 3;
  }
}

}  // namespace
}  // namespace strata::clipmap
