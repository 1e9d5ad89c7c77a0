// geometry.clipmap's height clipmap windows: every point a level's vertices may sample lies inside its window with
// its bilinear neighbours, anywhere on the body (by the antimeridian, at Gale crater, by both poles, from the
// coarsest level to centimetres); longitude texels change in powers of two; a window moved samples only the texels
// it moved in, and together with those it kept holds every texel.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include <glm/glm.hpp>

#include "height_windows.hpp"

namespace strata::clipmap {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTexels = 256;

glm::dvec2 degrees(double lon, double lat) { return glm::radians(glm::dvec2(lon, lat)); }

// The point `angle` rad from `from` (lon, lat) toward `azimuth` (clockwise from north), in double by way of unit
// vectors, whose latitude atan2 keeps by the poles; its longitude within half a turn of the reference's, as the
// vertex shader measures it.
glm::dvec2 destination(glm::dvec2 from, double angle, double azimuth) {
  const glm::dvec3 up(std::cos(from.y) * std::cos(from.x), std::cos(from.y) * std::sin(from.x), std::sin(from.y));
  const glm::dvec3 east(-std::sin(from.x), std::cos(from.x), 0.0);
  const glm::dvec3 north = glm::cross(up, east);
  const glm::dvec3 p = std::cos(angle) * up + std::sin(angle) * (std::cos(azimuth) * north + std::sin(azimuth) * east);
  const double lon = std::atan2(p.y, p.x);
  return {from.x + std::remainder(lon - from.x, 2.0 * kPi), std::atan2(p.z, std::hypot(p.x, p.y))};
}

// Whether a bilinear sample at `point` reads texels of the window only: along longitude unless it spans the turn.
bool insideWithNeighbours(const HeightWindow& window, glm::dvec2 reference, glm::dvec2 point) {
  const glm::dvec2 position = (point - reference - cornerFromReference(window, reference)) / window.texel - 0.5;
  const auto inside = [](double p) { return std::floor(p) >= 0.0 && std::floor(p) + 1.0 <= kTexels - 1; };
  return inside(position.y) && (window.wholeTurn || inside(position.x));
}

const std::pair<const char*, glm::dvec2> kPlaces[] = {
    {"lon 0, lat 0", degrees(0.0, 0.0)},           {"lon 10, lat 20", degrees(10.0, 20.0)},
    {"Gale crater", degrees(137.4, -4.6)},         {"by the antimeridian", degrees(179.9999, 12.0)},
    {"west of it", degrees(-179.9999, -33.0)},     {"at 70 north", degrees(45.0, 70.0)},
    {"by the north pole", degrees(-120.0, 89.99)}, {"by the south pole", degrees(60.0, -89.9999)},
    {"on the north pole", degrees(0.0, 90.0)}};

TEST(HeightWindows, EveryPointOfALevelsCapLiesInsideItsWindowWithItsNeighbours) {
  for (const auto& [name, reference] : kPlaces)
    for (int level = 0; level <= 36; ++level) {
      const HeightWindow window = heightWindow(level, reference, kTexels);
      const double angle = kPi * std::exp2(-level);
      EXPECT_TRUE(insideWithNeighbours(window, reference, reference)) << name << ", level " << level;
      for (int k = 0; k < 256; ++k)
        for (const double share : {0.5, 1.0}) {
          const glm::dvec2 point = destination(reference, share * angle, 2.0 * kPi * k / 256.0);
          ASSERT_TRUE(insideWithNeighbours(window, reference, point))
              << name << ", level " << level << ", azimuth " << 360.0 * k / 256.0 << " deg, " << share << " of the cap";
        }
    }
}

TEST(HeightWindows, LongitudeTexelsStepByQuarterOctavesOfTheLatitudes) {
  for (const auto& [name, reference] : kPlaces)
    for (int level = 2; level <= 36; ++level) {
      const HeightWindow window = heightWindow(level, reference, kTexels);
      if (window.wholeTurn) {
        EXPECT_DOUBLE_EQ(window.texel.x, 2.0 * kPi / kTexels) << name << ", level " << level;
        continue;
      }
      const double ratio = 4.0 * std::log2(window.texel.x / window.texel.y);
      EXPECT_NEAR(ratio, std::round(ratio), 1e-9) << name << ", level " << level;
    }
  const HeightWindow atTheEquator = heightWindow(20, degrees(10.0, 0.0), kTexels);
  EXPECT_EQ(atTheEquator.texel.x, atTheEquator.texel.y) << "on the equator a texel is as wide as it is high";
  const HeightWindow offIt = heightWindow(20, degrees(10.0, -3.3), kTexels);
  EXPECT_DOUBLE_EQ(offIt.texel.x, std::exp2(0.25) * offIt.texel.y) << "3.3 degrees off it, a quarter octave wider";
  const HeightWindow at70 = heightWindow(20, degrees(10.0, 70.0), kTexels);
  EXPECT_DOUBLE_EQ(at70.texel.x, std::exp2(1.75) * at70.texel.y)
      << "at 70 degrees a cap spans 1 / cos 70 = 2.9 times the longitude: 2^1.75 = 3.4";
}

TEST(HeightWindows, ACapHoldingAPoleSpansTheTurn) {
  const HeightWindow window =
      heightWindow(6, degrees(30.0, 88.0), kTexels);  // 2.8 degrees about a point 2 from the pole
  EXPECT_TRUE(window.wholeTurn);
  EXPECT_EQ(window.origin.x, 0);
  EXPECT_FALSE(heightWindow(7, degrees(30.0, 88.0), kTexels).wholeTurn) << "1.4 degrees about it does not";
}

// Moving the window by (east, north) texels of its lattice: the texels sampled and those kept cover the new window,
// and no more are sampled than moved in.
void expectMovedInSampled(glm::dvec2 reference, glm::dvec2 by, int level) {
  const HeightWindow held = heightWindow(level, reference, kTexels);
  const HeightWindow wanted = heightWindow(level, reference + by * held.texel, kTexels);
  ASSERT_EQ(held.texel, wanted.texel);
  const std::vector<TexelBlock> blocks = texelsToSample(held, wanted, kTexels);
  const glm::i64vec2 moved = wanted.origin - held.origin;
  std::int64_t sampled = 0;
  for (const TexelBlock& block : blocks) sampled += std::int64_t(block.count.x) * block.count.y;
  EXPECT_LE(sampled, (std::abs(moved.x) + std::abs(moved.y)) * kTexels);
  for (int x = 0; x < kTexels; ++x)
    for (int y = 0; y < kTexels; ++y) {
      const glm::i64vec2 lattice = wanted.origin + glm::i64vec2(x, y);
      const bool kept = glm::all(glm::greaterThanEqual(lattice, held.origin)) &&
                        glm::all(glm::lessThan(lattice, held.origin + std::int64_t(kTexels)));
      bool inBlock = false;
      for (const TexelBlock& block : blocks)
        inBlock = inBlock || (x >= block.first.x && x < block.first.x + block.count.x && y >= block.first.y &&
                              y < block.first.y + block.count.y);
      ASSERT_TRUE(kept || inBlock) << "texel " << x << ", " << y << " after a move of " << by.x << ", " << by.y;
    }
}

TEST(HeightWindows, AMovedWindowSamplesTheTexelsItMovedIn) {
  for (const glm::dvec2 by : {glm::dvec2(3.2, 0.0), glm::dvec2(-7.5, 0.0), glm::dvec2(0.0, 2.4), glm::dvec2(0.0, -40.0),
                              glm::dvec2(5.5, -9.1), glm::dvec2(-100.0, 100.0)}) {
    expectMovedInSampled(degrees(137.4, -4.6), by, 18);
    expectMovedInSampled(degrees(179.9999, 12.0), by, 24);
  }
}

TEST(HeightWindows, AWindowStillSamplesNothingAndANewOneEverything) {
  const HeightWindow window = heightWindow(12, degrees(10.0, 20.0), kTexels);
  EXPECT_TRUE(texelsToSample(window, window, kTexels).empty());
  const std::vector<TexelBlock> whole{{{0, 0}, {kTexels, kTexels}}};
  EXPECT_EQ(texelsToSample(std::nullopt, window, kTexels), whole) << "nothing held";
  EXPECT_EQ(texelsToSample(heightWindow(12, degrees(10.0, 80.0), kTexels), window, kTexels), whole)
      << "another longitude texel";
  EXPECT_EQ(texelsToSample(heightWindow(12, degrees(40.0, 20.0), kTexels), window, kTexels), whole)
      << "moved by more than its width";
}

TEST(HeightWindows, TexturesKeepTexelsWhereTheirLatticeIndexWraps) {
  HeightWindow window;
  window.origin = {-1, 2 * kTexels + 3};
  EXPECT_EQ(textureOffset(window, kTexels), glm::ivec2(kTexels - 1, 3));
}

}  // namespace
}  // namespace strata::clipmap
