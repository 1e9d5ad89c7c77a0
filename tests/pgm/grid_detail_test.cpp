// geometry.pgm's grid by screen-space error (grid_detail.hpp): the bare Earth seen whole takes a small share of the
// thesis's 1024 x 1024 rays, and the coarser the grid, the larger its error; relief whose blocks show it smooth takes
// fewer rays than the same relief known only as a range; an eye 2 m above relief, or a pixel error of 0, takes the
// whole grid.
#include <gtest/gtest.h>

#include <cmath>

#include "grid_detail.hpp"

namespace strata::pgm {
namespace {

constexpr double kEarth = 6371000.0;
constexpr glm::ivec2 kLargest{1024, 1024};
constexpr double kPixelsPerRadian = 1146.0;  // 720 pixels over a vertical field of view of 36 degrees

GridScene sceneFrom(double altitude, RegionalHeights visible) {
  const double distance = kEarth + altitude;
  return {.radius = kEarth,
          .eyeDistance = distance,
          .pixelsPerRadian = kPixelsPerRadian,
          .visible = visible,
          .visibleWidth = 2.0 * std::acos(kEarth / distance)};
}

// The sampling camera's image of the whole body from `distance`: the visible disc's tangent both ways.
glm::dvec2 discExtent(double distance) { return glm::dvec2(2.0 * std::tan(std::asin(kEarth / distance))); }

TEST(GridDetail, TheBareEarthSeenWholeTakesFewRays) {
  const GridScene scene = sceneFrom(2.0e7, {});
  const glm::ivec2 grid = gridForError(kLargest, discExtent(scene.eyeDistance), scene, 1.0);
  EXPECT_LE(grid.x, 256);
  EXPECT_GT(grid.x - 1, kFewestCells - 1);
  EXPECT_LT(gridError(scene, 0.01), gridError(scene, 0.02));
  EXPECT_LE(gridError(scene, discExtent(scene.eyeDistance).x / (grid.x - 1)), 1.0);
}

TEST(GridDetail, SmoothReliefTakesFewerRaysThanRelief) {
  const HeightRange relief{-100000.0, 100000.0};
  const GridScene smooth = sceneFrom(2.0e7, {relief, BlockRelief{3000.0, 0.03}});
  const GridScene rough = sceneFrom(2.0e7, {relief});
  const glm::dvec2 extent = discExtent(smooth.eyeDistance);
  EXPECT_LT(gridForError(kLargest, extent, smooth, 1.0).x, gridForError(kLargest, extent, rough, 1.0).x);
}

TEST(GridDetail, ReliefCloseByOrNoPixelErrorTakesTheWholeGrid) {
  const GridScene low = sceneFrom(2.0, {{0.0, 500.0}});
  EXPECT_EQ(gridForError(kLargest, glm::dvec2(1.0), low, 1.0), kLargest);
  const GridScene bare = sceneFrom(2.0e7, {});
  EXPECT_EQ(gridForError(kLargest, discExtent(bare.eyeDistance), bare, 0.0), kLargest);
}

}  // namespace
}  // namespace strata::pgm
