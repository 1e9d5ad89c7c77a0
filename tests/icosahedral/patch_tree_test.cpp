// The patch tree (plugins/geometry-icosahedral/patch_tree.hpp) from orbit and from the ground: it refines
// until no visible patch shows more than its pixel error, keeps within its number of visible patches and
// stays put while the view does, neighbouring leaves differ by at most one level with the coarser edges
// flagged, and no terrain the eye can see is culled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <strata/body.hpp>
#include <strata/camera.hpp>

#include "fly_in_path.hpp"
#include "patch_shell.hpp"
#include "patch_tree.hpp"
#include "planet_bounds.hpp"

namespace strata::icosahedral {
namespace {

constexpr double kEarth = 6371000.0;

View viewFrom(const Camera& camera) { return makeView(Body{"Earth", kEarth}, camera, 1280, 720); }

// No error is small enough: `patches` caps the tree wherever it looks, as it did before the tree followed the
// error, and still does for a view whose error asks for more than the cap.
constexpr PatchTreeSettings kCappedByPatches{.patches = 300, .pixelError = 0.0};

// Settles the tree, which a still view must then leave as it is.
void settle(PatchTree& tree, std::span<const ViewVolume> views) {
  tree.settle(views);
  for (int frame = 0; frame < 10; ++frame)
    ASSERT_EQ(tree.update(views), 0) << "a settled tree must not keep changing under a still view";
}

// Every alive leaf, by id.
std::vector<std::int32_t> leaves(const PatchTree& tree) {
  std::vector<std::int32_t> ids;
  const PatchTopology& topology = tree.topology();
  for (std::int32_t id = 0; id < std::int32_t(topology.capacity()); ++id)
    if (topology[id].alive && topology[id].leaf()) ids.push_back(id);
  return ids;
}

// The leaf whose triangle holds the direction, found by brute force.
std::int32_t leafHolding(const PatchTree& tree, const std::vector<std::int32_t>& ids, const glm::dvec3& direction) {
  for (const std::int32_t id : ids)
    if (holds(tree.topology().cornersOf(id), direction)) return id;
  return -1;
}

// Seen from afar, patches lie at nearly one distance and a whole level splits at once: the count may
// rest anywhere from a quarter of `patches` up, but never above, and must not swing.
TEST(PatchTree, FromOrbitItKeepsWithinItsNumberOfPatchesAndStaysPut) {
  PatchTree tree(kEarth, {0.0, 0.0}, kCappedByPatches);
  const std::vector<ViewVolume> views{ViewVolume(viewFrom({.lon = 20, .lat = 40, .altitude = 2e7}))};
  settle(tree, views);
  EXPECT_LE(tree.visibleCount(), 300);
  EXPECT_GE(tree.visibleCount(), 75);
  EXPECT_EQ(int(tree.visiblePatches().size()), tree.visibleCount());
}

// Low and tilted, the patches span many distances: the count follows the detail scale closely.
TEST(PatchTree, FromALowTiltedViewItKeepsNearItsNumberOfPatches) {
  PatchTree tree(kEarth, {0.0, 0.0}, kCappedByPatches);
  const std::vector<ViewVolume> views{ViewVolume(viewFrom({.lon = 20, .lat = 40, .altitude = 3e3, .tilt = 70}))};
  settle(tree, views);
  EXPECT_LE(tree.visibleCount(), 300) << "largest detail scale " << std::ranges::max(tree.detailField().values());
  EXPECT_GE(tree.visibleCount(), 240);
}

// The whole Earth from 20,000 km, the peer benchmark's view (a): the bare sphere's chords miss it by under a
// pixel with the icosahedron's faces themselves, so the tree rests at the least detail, a fifth of the
// patches it kept when it filled `patches` (about 300, each 4^5 triangles).
TEST(PatchTree, FromOrbitTheBareSphereTakesAFifthOfItsPatches) {
  const std::vector<ViewVolume> views{ViewVolume(viewFrom({.lon = 10, .lat = 20, .altitude = 2e7, .fov = 36}))};
  PatchTree byError(kEarth, {0.0, 0.0});
  settle(byError, views);
  PatchTree byCount(kEarth, {0.0, 0.0}, kCappedByPatches);
  settle(byCount, views);
  std::printf("visible patches: %d by the pixel error, %d up to the cap\n", byError.visibleCount(),
              byCount.visibleCount());
  EXPECT_LE(byError.visibleCount(), 60);
  EXPECT_LE(5 * byError.visibleCount(), byCount.visibleCount());
}

// Every visible leaf's error, seen from its face-on distance, is at most the pixel error, from orbit, from a
// low tilted view and near a pole, with a cap the tree never reaches.
TEST(PatchTree, NoVisiblePatchShowsMoreThanItsPixelError) {
  constexpr PatchTreeSettings settings{.patches = 20000, .pixelError = 2.0};
  for (const Camera& camera : {Camera{.lon = 10, .lat = 20, .altitude = 2e6, .fov = 36},
                               Camera{.lon = 137.4, .lat = -4.6, .altitude = 5e3, .tilt = 60, .fov = 36},
                               Camera{.lon = -60, .lat = 88, .altitude = 1e5, .tilt = 30, .fov = 36}}) {
    const View view = viewFrom(camera);
    PatchTree tree(kEarth, {0.0, 0.0}, settings);
    settle(tree, std::vector<ViewVolume>{ViewVolume(view)});
    ASSERT_LT(tree.visibleCount(), settings.patches);
    const double pixelsPerRadian = ViewVolume(view).pixelsPerRadian();
    for (const std::int32_t id : leaves(tree)) {
      const PatchNode& node = tree.topology()[id];
      if (!node.visible || node.level == PatchTree::kDeepestLevel) continue;
      EXPECT_LE(tree.errorOf(id) * pixelsPerRadian / node.distance, settings.pixelError)
          << "level " << node.level << " at lat " << camera.lat;
    }
  }
}

// A patch splits where its face-on distance falls below its split distance: its level's nominal size, halved from
// level to level, times the largest detail scale over it.
TEST(PatchTree, PatchesNearerThanTheirSplitDistanceAreSplit) {
  PatchTree tree(kEarth, {0.0, 0.0});
  const View view = viewFrom({.lon = 5, .lat = 5, .altitude = 1e4, .tilt = 60});
  const std::vector<ViewVolume> views{ViewVolume(view)};
  settle(tree, views);
  for (const Patch& patch : tree.visiblePatches()) {
    if (patch.level == PatchTree::kDeepestLevel) continue;
    const float largest = std::max({patch.details[0], patch.details[1], patch.details[2]});
    if (patch.level >= DetailField::kLevel) {
      EXPECT_DOUBLE_EQ(tree.splitDistanceOf(patch), std::ldexp(tree.splitDistanceUnit() * largest, -patch.level));
    }
    EXPECT_GE(leastFaceOnDistance({patch.corners, kEarth, kEarth}, view.eye), tree.splitDistanceOf(patch))
        << "a visible leaf of level " << patch.level << " is near enough to be split";
  }
}

// No operations allowed: the tree and its detail scale stay as they were, wherever the eye has gone.
TEST(PatchTree, ATreeAllowedNoOperationsHoldsItsPatches) {
  PatchTree tree(kEarth, {0.0, 0.0});
  tree.settle(std::vector<ViewVolume>{ViewVolume(viewFrom({.lon = 0, .lat = 0, .altitude = 1e5, .tilt = 45}))});
  const std::vector<std::int32_t> before = leaves(tree);
  const std::vector<double> details = tree.detailField().values();
  const std::vector<ViewVolume> elsewhere{ViewVolume(viewFrom({.lon = 90, .lat = 30, .altitude = 1e3, .tilt = 80}))};
  EXPECT_EQ(tree.update(elsewhere, 0), 0);
  EXPECT_EQ(leaves(tree), before);
  EXPECT_EQ(tree.detailField().values(), details);
}

// The fly-in of [Kooima 2008, §5.1] as strata-bench-flyin flies it at 30 Hz, 10,000 km down to 300 m above an 8.7 km
// summit of a Mars-sized body: the default operations per frame keep up, frame after frame (the busiest frame made 38
// of its 64).
TEST(PatchTree, TheDefaultOperationsFollowAThirtyHertzFlyIn) {
  const FlyInPath flight{-74.0, 4.0, 8672.0};  // the summit strata-bench-flyin's survey finds
  PatchTree tree(FlyInPath::kMarsRadius, {-12000.0, 12000.0});
  int busiest = 0;
  for (int frame = 0; frame < FlyInPath::kFramesEachWay; ++frame) {
    const View view = makeView(Body{"Mars", FlyInPath::kMarsRadius}, flight.cameraAt(frame), 1280, 720);
    const std::vector<ViewVolume> views{ViewVolume(view)};
    if (frame == 0)
      tree.settle(views);
    else
      busiest = std::max(busiest, tree.update(views));
  }
  EXPECT_LT(busiest, PatchTreeSettings{}.operationsPerFrame);
}

// The deepest level among the visible patches.
int deepestLevel(const PatchTree& tree) {
  int level = 0;
  for (const Patch& patch : tree.visiblePatches()) level = std::max(level, patch.level);
  return level;
}

// Each patch's heights, as geometry.icosahedral takes them from source.procedural (planet_bounds.hpp):
// the planet's bounds over the patch's sampled cap, within the whole range.
PatchHeights proceduralHeights(const procedural::PlanetModel& planet, const HeightRange& range) {
  return [&planet, range](const SphericalTriangle& corners) {
    const SphericalCap cap = sampledCap(corners, 5);
    const procedural::HeightBounds bounds = procedural::heightsWithin(planet, cap.centre, cap.angle);
    return RegionalHeights{{std::max(bounds.least, range.lowest), std::min(bounds.greatest, range.highest)}};
  };
}

// The same fly-in with each patch measured on the planet's own heights (source.procedural's bounds over its
// sampled cap, planet_bounds.hpp), as geometry.icosahedral measures it. The path falls geometrically in
// altitude above the sphere, so measured from the ground its last frame closes from 733 m to 300 m above it
// and asks more than a frame's operations; every frame before it keeps within them, and the next (held at
// the bottom) catches up. There the deepest patch is as deep as at the eye's height above the ground below
// it over the bare sphere; measured on the sphere, 9 km up, it is several levels coarser.
TEST(PatchTree, OnTheProceduralPlanetsOwnHeightsTheFlyInSplitsAsAboveTheGround) {
  const FlyInPath flight{-74.0, 4.0, 8672.0};
  const procedural::PlanetModel planet({}, FlyInPath::kMarsRadius);
  const HeightRange range{-12000.0, 12000.0};
  const PatchHeights own = proceduralHeights(planet, range);
  const Body mars{"Mars", FlyInPath::kMarsRadius};
  const auto viewsAt = [&](const Camera& camera) {
    return std::vector<ViewVolume>{ViewVolume(makeView(mars, camera, 1280, 720, range))};
  };
  PatchTree tree(FlyInPath::kMarsRadius, range, kCappedByPatches, own);
  tree.settle(viewsAt(flight.cameraAt(0)));
  int busiest = 0;
  for (int frame = 1; frame < FlyInPath::kFramesEachWay - 1; ++frame)
    busiest = std::max(busiest, tree.update(viewsAt(flight.cameraAt(frame))));
  EXPECT_LT(busiest, PatchTreeSettings{}.operationsPerFrame);
  const Camera bottom = flight.cameraAt(FlyInPath::kFramesEachWay - 1);
  tree.update(viewsAt(bottom));
  EXPECT_LT(tree.update(viewsAt(bottom)), PatchTreeSettings{}.operationsPerFrame);
  settle(tree, viewsAt(bottom));
  Camera aboveSphere = bottom;
  aboveSphere.altitude -= planet.height(directionOf(glm::radians(glm::dvec2(bottom.lon, bottom.lat))));
  PatchTree bare(FlyInPath::kMarsRadius, {0.0, 0.0}, kCappedByPatches);
  settle(bare, std::vector<ViewVolume>{ViewVolume(makeView(mars, aboveSphere, 1280, 720))});
  PatchTree onSphere(FlyInPath::kMarsRadius, range, kCappedByPatches);
  settle(onSphere, viewsAt(bottom));
  std::printf("deepest levels: %d on the planet's heights, %d %.0f m above the sphere, %d measured on the sphere\n",
              deepestLevel(tree), deepestLevel(bare), aboveSphere.altitude, deepestLevel(onSphere));
  EXPECT_NEAR(deepestLevel(tree), deepestLevel(bare), 1);
  EXPECT_LE(deepestLevel(onSphere), deepestLevel(tree) - 4);
}

// Rough terrain close by shows its relief as error, which the bare sphere has not: at the fly-in's last
// frame, 300 m above the procedural planet's summit, the tree on the planet's own heights takes more than
// twice the patches of the bare sphere seen from as high above it, each with the default pixel error.
TEST(PatchTree, RoughTerrainCloseByTakesMorePatchesThanTheBareSphere) {
  const FlyInPath flight{-74.0, 4.0, 8672.0};
  const procedural::PlanetModel planet({}, FlyInPath::kMarsRadius);
  const HeightRange range{-12000.0, 12000.0};
  const Body mars{"Mars", FlyInPath::kMarsRadius};
  const Camera bottom = flight.cameraAt(FlyInPath::kFramesEachWay - 1);
  PatchTree rough(FlyInPath::kMarsRadius, range, {}, proceduralHeights(planet, range));
  settle(rough, std::vector<ViewVolume>{ViewVolume(makeView(mars, bottom, 1280, 720, range))});
  Camera aboveSphere = bottom;
  aboveSphere.altitude -= planet.height(directionOf(glm::radians(glm::dvec2(bottom.lon, bottom.lat))));
  PatchTree bare(FlyInPath::kMarsRadius, {0.0, 0.0});
  settle(bare, std::vector<ViewVolume>{ViewVolume(makeView(mars, aboveSphere, 1280, 720))});
  std::printf("visible patches: %d over the rough planet, %d over the bare sphere\n", rough.visibleCount(),
              bare.visibleCount());
  EXPECT_GT(rough.visibleCount(), 2 * bare.visibleCount());
}

// How the terrain's relief scales with size decides how much of a patch's relief its vertex spacing may hide
// (PatchTree::errorOf): a swell sloping 5 % everywhere, whose relief grows as the size (the layer's finest blocks,
// 2 mrad wide, holding their share of it), takes under half the patches that the same relief takes where the
// blocks say it is Brownian (their relief the patch's times the square root of the sizes' ratio) or where no
// blocks are known; the last two, both rough, take the same. Where the blocks also know the swell's curvature,
// that of a slope turning by 1 % over 100 km (linear interpolation misses it by a second-order share), it takes
// under half the swell's again: measured 49, 163 and 1,468 patches. Each keeps every visible patch within its
// pixel error.
TEST(PatchTree, SmoothReliefTakesFewerPatchesThanRoughReliefOfTheSameRange) {
  constexpr double kSlope = 0.05, kBlockWidth = 2e-3, kCurvature = 0.01 * kEarth * kEarth / 1e5;  // m per rad^2
  enum class Blocks { kCurved, kSmooth, kBrownian, kUnknown };
  const auto heightsWith = [](Blocks blocks) -> PatchHeights {
    return [blocks](const SphericalTriangle& corners) {
      const double width = 2.0 * capAround(corners).angle, relief = kSlope * kEarth * width;
      RegionalHeights heights{{0.0, relief}};
      if (blocks == Blocks::kSmooth) heights.finest = BlockRelief{kSlope * kEarth * kBlockWidth, kBlockWidth};
      if (blocks == Blocks::kCurved)
        heights.finest = BlockRelief{kSlope * kEarth * kBlockWidth, kBlockWidth, kCurvature, kBlockWidth / 8.0};
      if (blocks == Blocks::kBrownian)
        heights.finest = BlockRelief{relief * std::sqrt(kBlockWidth / width), kBlockWidth};
      return heights;
    };
  };
  const View view = makeView(Body{"Earth", kEarth}, {.lon = 137.4, .lat = -4.6, .altitude = 2e5, .tilt = 45, .fov = 36},
                             1280, 720, {0.0, kSlope * kEarth * std::numbers::pi});
  const std::vector<ViewVolume> views{ViewVolume(view)};
  const PatchTreeSettings settings{.patches = 20000};
  std::vector<int> counts;
  for (const Blocks blocks : {Blocks::kCurved, Blocks::kSmooth, Blocks::kBrownian, Blocks::kUnknown}) {
    PatchTree tree(kEarth, {0.0, kSlope * kEarth * std::numbers::pi}, settings, heightsWith(blocks));
    settle(tree, views);
    ASSERT_LT(tree.visibleCount(), settings.patches);
    for (const std::int32_t id : leaves(tree)) {
      const PatchNode& node = tree.topology()[id];
      if (!node.visible) continue;
      EXPECT_LE(tree.errorOf(id) * views[0].pixelsPerRadian() / node.distance, settings.pixelError);
    }
    counts.push_back(tree.visibleCount());
  }
  std::printf("visible patches: %d curved, %d smooth, %d Brownian, %d without blocks\n", counts[0], counts[1],
              counts[2], counts[3]);
  EXPECT_LT(2 * counts[0], counts[1]);
  EXPECT_LT(2 * counts[1], counts[2]);
  EXPECT_EQ(counts[2], counts[3]);
}

// The detail scale is a field over the body (DetailField): relief in one region asks for detail there only.
// Relief of 5 % of a patch's width, as rough as Brownian (its blocks unknown), within 2 degrees of lon 137.4,
// lat -4.6 and none elsewhere, seen from 3,000 km tilted 30 degrees toward it: the field rises there and stays at
// its least far from it, the patches far from the relief are no deeper than on the bare sphere, and the whole
// takes under half the patches the same relief everywhere takes (measured: 168, 934, and 40 on the bare sphere).
// Each keeps every visible patch within its pixel error. The lattice's triangles are some 8 degrees across: a view
// spanning only one or two of them, from 1,000 km, took 809 patches against 1,182.
TEST(PatchTree, ReliefInOneRegionAsksForDetailThereOnly) {
  constexpr double kSlope = 0.05, kRegion = 2.0;  // degrees
  const glm::dvec3 rough = directionOf(glm::radians(glm::dvec2(137.4, -4.6)));
  const auto heights = [rough](bool everywhere) -> PatchHeights {
    return [rough, everywhere](const SphericalTriangle& corners) {
      const SphericalCap cap = capAround(corners);
      const bool near = everywhere || angleBetween(cap.centre, rough) - cap.angle < glm::radians(kRegion);
      return RegionalHeights{{0.0, near ? kSlope * kEarth * 2.0 * cap.angle : 0.0}};
    };
  };
  const double highest = kSlope * kEarth * std::numbers::pi;
  const View view = makeView(Body{"Earth", kEarth}, {.lon = 137.4, .lat = -12, .altitude = 3e6, .tilt = 30, .fov = 36},
                             1280, 720, {0.0, highest});
  const std::vector<ViewVolume> views{ViewVolume(view)};
  const PatchTreeSettings settings{.patches = 20000};
  PatchTree regional(kEarth, {0.0, highest}, settings, heights(false));
  PatchTree everywhere(kEarth, {0.0, highest}, settings, heights(true));
  PatchTree bare(kEarth, {0.0, 0.0}, settings);
  for (PatchTree* tree : {&regional, &everywhere, &bare}) settle(*tree, views);
  int deepestFar = 0, deepestBare = 0;
  for (const Patch& patch : regional.visiblePatches())
    if (angleBetween(capAround(patch.corners).centre, rough) > glm::radians(30.0))
      deepestFar = std::max(deepestFar, patch.level);
  for (const Patch& patch : bare.visiblePatches()) deepestBare = std::max(deepestBare, patch.level);
  const std::vector<double>& field = regional.detailField().values();
  std::printf("visible patches: %d with relief in one region, %d everywhere, %d bare; detail %.2f to %.2f\n",
              regional.visibleCount(), everywhere.visibleCount(), bare.visibleCount(), std::ranges::min(field),
              std::ranges::max(field));
  EXPECT_LE(deepestFar, deepestBare);
  EXPECT_EQ(std::ranges::min(field), PatchTree::kLeastDetail);
  EXPECT_GT(std::ranges::max(field), 4.0 * PatchTree::kLeastDetail);
  EXPECT_LT(2 * regional.visibleCount(), everywhere.visibleCount());
  int showing = 0;
  for (const std::int32_t id : leaves(regional)) {
    const PatchNode& node = regional.topology()[id];
    showing += int(node.visible && regional.errorOf(id) * view.pixelsPerRadian() / node.distance > settings.pixelError);
  }
  EXPECT_EQ(showing, 0) << "visible patches whose error shows";
}

// Just across each edge of every leaf lies a leaf at most one level apart; it is one level coarser
// exactly where the patch flags that edge as coarse.
void expectOneLevelApartWithCoarseEdgesFlagged(const PatchTree& tree) {
  const std::vector<std::int32_t> ids = leaves(tree);
  const PatchTopology& topology = tree.topology();
  for (const std::int32_t id : ids) {
    const SphericalTriangle t = topology.cornersOf(id);
    for (int e = 0; e < 3; ++e) {
      const glm::dvec3 a = t[std::size_t(e)], b = t[std::size_t(e + 1) % 3];
      const glm::dvec3 outward = -glm::normalize(glm::cross(a, b));
      bool coarser = false;
      for (const double along : {0.25, 0.75}) {
        const glm::dvec3 edgePoint = glm::normalize(a * (1.0 - along) + b * along);
        const std::int32_t neighbour =
            leafHolding(tree, ids, glm::normalize(edgePoint + outward * 1e-3 * glm::length(a - b)));
        ASSERT_GE(neighbour, 0);
        EXPECT_LE(std::abs(topology[neighbour].level - topology[id].level), 1);
        coarser = coarser || topology[neighbour].level < topology[id].level;
      }
      EXPECT_EQ(coarser, topology.across(id, e) < 0) << "leaf " << id << " edge " << e;
    }
  }
}

TEST(PatchTree, NeighboursDifferByAtMostOneLevelFromTheGround) {
  PatchTree tree(kEarth, {0.0, 0.0});
  const std::vector<ViewVolume> views{ViewVolume(viewFrom({.lon = 179.99, .lat = 10, .altitude = 2.0, .tilt = 60}))};
  settle(tree, views);
  expectOneLevelApartWithCoarseEdgesFlagged(tree);
  EXPECT_GE(deepestLevel(tree), 20) << "2 m up, the patch below the eye should be a few metres across";
}

// Each patch measured on its own heights (CDLOD's bounding boxes, Strugar 2009, as spherical shells): 2 m
// above a plateau 3 km high, in terrain that reaches from 0 to 5 km elsewhere, the tree splits as it would 2 m
// above the bare sphere. Without them it measures on the sphere and splits as for a view from 3 km.
TEST(PatchTree, TwoMetresAboveAPlateauSplitsAsTwoMetresAboveTheSphere) {
  const Camera overSphere{.lon = 137.4, .lat = -4.6, .altitude = 2.0, .tilt = 60};
  Camera overPlateau = overSphere;
  overPlateau.altitude = 3002.0;
  const HeightRange terrain{0.0, 5000.0};
  const glm::dvec3 below = glm::normalize(viewFrom(overSphere).eye);
  // The plateau: everything within 20 km of the point below the eye.
  const PatchHeights plateau = [&](const SphericalTriangle& corners) {
    for (const glm::dvec3& corner : corners)
      if (std::acos(std::min(glm::dot(corner, below), 1.0)) * kEarth > 20e3) return RegionalHeights{terrain};
    return RegionalHeights{{3000.0, 3000.0}};
  };
  PatchTree bare(kEarth, {0.0, 0.0}, kCappedByPatches);
  settle(bare, std::vector<ViewVolume>{ViewVolume(viewFrom(overSphere))});
  const std::vector<ViewVolume> plateauViews{
      ViewVolume(makeView(Body{"Earth", kEarth}, overPlateau, 1280, 720, terrain))};
  PatchTree own(kEarth, terrain, kCappedByPatches, plateau);
  settle(own, plateauViews);
  PatchTree whole(kEarth, terrain, kCappedByPatches);
  settle(whole, plateauViews);
  EXPECT_GE(deepestLevel(bare), 20);
  EXPECT_NEAR(deepestLevel(own), deepestLevel(bare), 1);
  std::printf("deepest levels: %d over the sphere, %d over the plateau, %d measured on the sphere\n",
              deepestLevel(bare), deepestLevel(own), deepestLevel(whole));
  EXPECT_LE(deepestLevel(whole), deepestLevel(bare) - 8) << "3 km is 2^10 times 2 m: about ten levels coarser";
}

// Points of terrain that the eye sees (in its frustum, the segment to them clear of the sphere below
// all terrain) lie in visible patches, mountains beyond the bare sphere's horizon included.
TEST(PatchTree, NoTerrainTheEyeCanSeeIsCulled) {
  const HeightRange heights{0.0, 8848.0};
  PatchTree tree(kEarth, heights);
  const View view = viewFrom({.lon = -30, .lat = 45, .altitude = 1000.0, .heading = 70, .tilt = 88});
  const std::vector<ViewVolume> views{ViewVolume(view)};
  settle(tree, views);
  const std::vector<std::int32_t> ids = leaves(tree);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> across(-1.0, 1.0), height(heights.lowest, heights.highest),
      distance(0.0, 450e3);
  int seen = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // A direction in the frustum, followed to a distance, dropped onto a terrain height there.
    const double tanHalf = std::tan(0.5 * view.verticalFov);
    const glm::dvec3 eyeRay(across(random) * tanHalf * 1280.0 / 720.0, across(random) * tanHalf, -1.0);
    const glm::dvec3 ray = glm::transpose(view.planetToEye) * glm::normalize(eyeRay);
    const glm::dvec3 direction = glm::normalize(view.eye + ray * distance(random));
    const glm::dvec3 point = direction * (kEarth + height(random));
    const glm::dvec3 towardPoint = view.planetToEye * (point - view.eye);
    if (towardPoint.z >= -view.near || std::abs(towardPoint.x) > -towardPoint.z * tanHalf * 1280.0 / 720.0 ||
        std::abs(towardPoint.y) > -towardPoint.z * tanHalf)
      continue;
    const glm::dvec3 d = point - view.eye;
    const double t = std::clamp(-glm::dot(view.eye, d) / glm::dot(d, d), 0.0, 1.0);
    if (glm::length(view.eye + t * d) < kEarth + heights.lowest) continue;
    ++seen;
    const std::int32_t leaf = leafHolding(tree, ids, direction);
    ASSERT_GE(leaf, 0);
    EXPECT_TRUE(tree.topology()[leaf].visible) << "trial " << trial;
  }
  EXPECT_GT(seen, 1000);
}

TEST(PatchTree, EveryViewIsServedAtOnce) {
  PatchTree tree(kEarth, {0.0, 0.0}, kCappedByPatches);
  const std::vector<ViewVolume> views{
      ViewVolume(viewFrom({.lon = 0, .lat = 0, .altitude = 5e5, .heading = 90, .tilt = 80})),
      ViewVolume(viewFrom({.lon = 0, .lat = 0, .altitude = 5e5, .heading = 270, .tilt = 80}))};
  settle(tree, views);
  int east = 0, west = 0;
  for (const Patch& patch : tree.visiblePatches()) {
    const glm::dvec3 centre = glm::normalize(patch.corners[0] + patch.corners[1] + patch.corners[2]);
    (centre.y > 0.0 ? east : west) += 1;
  }
  EXPECT_GT(east, 100);
  EXPECT_GT(west, 100);
}

// Flying round the planet and back leaves a tree of the size the view needs, not of the flight.
TEST(PatchTree, TheTreeFollowsTheViewAndForgetsWhatItLeft) {
  PatchTree tree(kEarth, {0.0, 0.0});
  std::vector<ViewVolume> views{ViewVolume(viewFrom({.lon = 0, .lat = 0, .altitude = 1e5, .tilt = 45}))};
  settle(tree, views);
  const std::size_t start = leaves(tree).size();
  for (double lon = 0.0; lon <= 360.0; lon += 10.0) {
    views = {ViewVolume(viewFrom({.lon = lon, .lat = 0, .altitude = 1e5, .tilt = 45}))};
    settle(tree, views);
  }
  EXPECT_LE(leaves(tree).size(), start + start / 4);
}

}  // namespace
}  // namespace strata::icosahedral
