// geometry.clipmap's choice of levels: the horizon widened for mountains behind it, judged by lines of sight cast in
// double; a pixel's footprint below the eye and the fill cap about it; and the levels holding the horizon and the cap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "drawn_levels.hpp"
#include "hemisphere_rings.hpp"

namespace strata::clipmap {
namespace {

constexpr double kEarth = 6371000.0;

// Whether the straight line from a point `altitude` above the sphere of `radius` at colatitude 0 to a point
// `height` above it at colatitude `theta` clears the sphere of `lowest` between them: where the line comes nearest
// the centre at either end, nothing between hides one from the other.
bool inSight(double radius, double altitude, double height, double theta, double lowest) {
  const glm::dvec2 eye(0.0, radius + altitude), peak = (radius + height) * glm::dvec2(std::sin(theta), std::cos(theta));
  const glm::dvec2 d = peak - eye;
  const double t = -glm::dot(eye, d) / glm::dot(d, d);
  return t <= 0.0 || t >= 1.0 || glm::length(eye + t * d) >= lowest;
}

TEST(DrawnLevels, TheHorizonHoldsEveryPeakInSightAndNoMore) {
  for (const HeightRange heights : {HeightRange{0, 0}, HeightRange{-11000, 8848}, HeightRange{-500, 240000}})
    for (const double altitude : {2.0, 5000.0, 3.0e5, 2.0e7}) {
      const double horizon = horizonColatitude(kEarth, altitude, heights);
      const double lowest = kEarth + heights.lowest;
      EXPECT_TRUE(inSight(kEarth, altitude, heights.highest, horizon * (1.0 - 1e-3), lowest)) << altitude;
      EXPECT_FALSE(inSight(kEarth, altitude, heights.highest, horizon * (1.0 + 1e-3), lowest)) << altitude;
    }
  EXPECT_DOUBLE_EQ(horizonColatitude(kEarth, 2.0e7, {}), std::acos(kEarth / (kEarth + 2.0e7)))
      << "the bare sphere: Eq. 6";
}

TEST(DrawnLevels, APixelBelowTheEyeIsMeasuredFromTheGroundNearest) {
  const double pixel = 1e-3;  // rad
  EXPECT_DOUBLE_EQ(pixelColatitude(kEarth, 5000.0, {}, pixel), 5000.0 * std::tan(pixel) / kEarth) << "Eqs. 7 and 8";
  EXPECT_DOUBLE_EQ(pixelColatitude(kEarth, 3002.0, {0, 3000}, pixel), 2.0 * std::tan(pixel) / kEarth)
      << "2 m above a plateau 3 km high";
}

TEST(DrawnLevels, TheCapIsFourPixelsWideAndTheRingsOutsideItASeventhOfAPixelApart) {
  const double pixel = 1e-6, cap = capColatitude(pixel);
  EXPECT_DOUBLE_EQ(cap, 4.0 * pixel);
  const double spacing = cap - cap * std::exp2(-1.0 / 20.0);  // the ring at the cap's edge to the next one in
  EXPECT_NEAR(spacing / pixel, 1.0 / 7.3, 0.01) << "at the paper's m = 20";
}

TEST(DrawnLevels, TheLevelsHoldTheHorizonAndTheCap) {
  for (const double horizon : {1.5, 0.04, 8e-4})
    for (const double cap : {1e-4, 1e-7, 3e-10}) {
      if (cap >= horizon) continue;
      const DrawnLevels drawn = drawnLevels(horizon, cap, 40);
      EXPECT_LT(ringColatitude((drawn.coarsest + 1) * 20, 20), horizon);
      EXPECT_GE(ringColatitude(drawn.coarsest * 20, 20), horizon);
      EXPECT_LT(ringColatitude((drawn.finest + 1) * 20, 20), cap) << "the finest level's inner edge lies in the cap";
      EXPECT_GE(ringColatitude(drawn.finest * 20, 20), cap);
    }
  EXPECT_EQ(drawnLevels(1.5, 1e-20, 40).finest, 39) << "no finer than the mesh";
}

}  // namespace
}  // namespace strata::clipmap
