// geometry.clipmap's sectors a view draws: every sector left out lies wholly outside one side of the view's
// frustum, every vertex of it at the lowest and at the highest ground, or where the eye lies between them, its parts
// below and above the eye each outside one side (so no triangle of it can show); and a view
// near the ground, tilted, leaves out most of the rings, where a view of the whole body leaves out none it sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

#include <glm/glm.hpp>

#include <strata/camera.hpp>

#include "drawn_levels.hpp"
#include "hemisphere_rings.hpp"
#include "sector_culling.hpp"

namespace strata::clipmap {
namespace {

constexpr double kMars = 3396190.0;
constexpr int kWidth = 1280, kHeight = 720;

// The frustum's sides (ahead, left, right, bottom, top) that eye-space point `p` lies outside of, a bit each.
unsigned outsideSides(const View& view, const glm::dvec3& p) {
  const glm::dvec2 t = view.halfFrameTangents();
  const double ahead = -p.z;
  const std::array<double, 5> sides = {ahead, p.x + t.x * ahead, -p.x + t.x * ahead, p.y + t.y * ahead,
                                       -p.y + t.y * ahead};
  unsigned outside = 0;
  for (std::size_t s = 0; s < sides.size(); ++s) outside |= sides[s] < 0.0 ? 1u << s : 0u;
  return outside;
}

struct Culled {
  std::size_t drawnTriangles = 0, levelTriangles = 0;
};

// Checks every sector of the drawn levels that visibleRanges leaves out, and counts what it keeps.
Culled checkCulling(const HemisphereRings& mesh, const View& view, const HeightRange& heights) {
  const double altitude = glm::length(view.eye) - kMars;
  const double pixel = pixelColatitude(kMars, altitude, heights, 1.0 / view.pixelsPerRadian());
  const DrawnLevels drawn = drawnLevels(horizonColatitude(kMars, altitude, heights), capColatitude(pixel), 40);
  const std::vector<IndexRange> ranges =
      visibleRanges(mesh, drawn, view, kMars, [&heights](const SphericalCap&) { return heights; });
  std::set<std::uint32_t> kept;
  Culled culled;
  for (const IndexRange& range : ranges) {
    culled.drawnTriangles += range.count / 3;
    for (std::uint32_t i = range.first; i < range.first + range.count; i += 3) kept.insert(i);
  }
  const glm::dmat3 localToEye = view.planetToEye * glm::transpose(planetToLocal(view.reference));
  const glm::dvec3 eyeLocal(0.0, 0.0, glm::length(view.eye));
  for (int level = drawn.coarsest; level <= drawn.finest; ++level)
    for (int sector = 0; sector < mesh.sectors; ++sector) {
      const IndexRange range = sectorRange(mesh, level, sector);
      culled.levelTriangles += range.count / 3;
      if (kept.count(range.first)) continue;
      const double eyeHeight = std::clamp(altitude, heights.lowest, heights.highest);
      for (const auto& [low, high] : {std::pair(heights.lowest, eyeHeight), std::pair(eyeHeight, heights.highest)}) {
        unsigned common = 0x1f;
        for (std::uint32_t i = range.first; i < range.first + range.count; ++i) {
          const HemisphereVertex& v = mesh.vertices[mesh.indices[i]];
          const glm::dvec3 s(v.east, v.north, 1.0 + double(v.upMinusOne));
          for (const double h : {low, high}) common &= outsideSides(view, localToEye * ((kMars + h) * s - eyeLocal));
        }
        EXPECT_NE(common, 0u) << "level " << level << " sector " << sector << " may show, yet is left out";
      }
    }
  return culled;
}

TEST(SectorCulling, WhatIsLeftOutLiesOutsideTheFrustum) {
  const HemisphereRings mesh = buildHemisphereRings({});
  const HeightRange relief{-8000, 21000};  // Mars's
  for (const Camera& camera : {Camera{30, 60, 3.0e6, 0, 30, 45}, Camera{137.4, -4.6, 5000, 30, 60, 36},
                               Camera{-179.99, 89.9, 200, 200, 80, 40}, Camera{10, -20, 2, 90, 45, 60}}) {
    const View view = makeView(Body{"Mars", kMars}, camera, kWidth, kHeight, relief);
    checkCulling(mesh, view, relief);
  }
}

// A view tilted 60 degrees over Gale with Mars's whole range of heights. From 30 km, above the highest ground, the
// sectors out of the frame's 60 degrees across and the rings below the eye are left out: 14% of the drawn levels'
// triangles are drawn (the paper expected 1/8 at a 90 degree field of view). From 5 km the eye lies within the
// range, and ground that may stand 30 m below it 100 m away would show: the wedges about it are drawn where their
// columns of possible ground meet the frustum, 48% in all; regional heights (a tiled raster's) narrow them.
TEST(SectorCulling, ATiltedViewNearTheGroundDrawsAFewSectorsAndAWholeBodyAll) {
  const HemisphereRings mesh = buildHemisphereRings({});
  const HeightRange relief{-8000, 21000};
  for (const auto& [altitude, share] : {std::pair(30000.0, 1.0 / 6.0), std::pair(5000.0, 1.0 / 2.0)}) {
    const Camera near{137.4, -4.6, altitude, 30, 60, 36};
    const Culled tilted = checkCulling(mesh, makeView(Body{"Mars", kMars}, near, kWidth, kHeight, relief), relief);
    EXPECT_LT(double(tilted.drawnTriangles), share * double(tilted.levelTriangles))
        << altitude << " m: " << tilted.drawnTriangles << " of " << tilted.levelTriangles;
  }
  const Camera whole{30, 20, 2.0e7, 0, 0, 36};
  const Culled seenWhole = checkCulling(mesh, makeView(Body{"Mars", kMars}, whole, kWidth, kHeight, relief), relief);
  EXPECT_EQ(seenWhole.drawnTriangles, seenWhole.levelTriangles + std::size_t(mesh.settings.steps));
}

}  // namespace
}  // namespace strata::clipmap
