// A raster's block ranges placed on the body (core/layers/src/block_caps.cpp): whatever texel a point of a
// cap samples, the cap's values hold it, and a cap that reaches beyond the raster says so; small caps get
// ranges about as tight as their blocks. Through the built-in projections' own inverse and forward, on a
// global longitude/latitude map seen across its seam and at its poles, a polar stereographic cap map and a
// small map far from longitude 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/page_pyramid.hpp>

#include "layers/block_caps.hpp"
#include "layers/healpix_page_caps.hpp"
#include "projection_cases.hpp"

namespace strata {
namespace {

constexpr double kEarth = 6371000.0;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// A field over the body with a different value at every texel: what the texels hold, by their centres.
double field(glm::dvec2 lonlat) { return 1000.0 * std::sin(3.0 * lonlat.x) * std::cos(lonlat.y) + 500.0 * lonlat.y; }

struct Raster {
  std::string terms;
  std::array<double, 6> geotransform;
  int width, height;
  bool repeatX;
};

glm::dvec2 texelOf(const Raster& raster, glm::dvec2 map) {
  const std::array<double, 6>& t = raster.geotransform;
  return {(map.x - t[0]) / t[1], (map.y - t[3]) / t[5]};  // north up, no rotation
}

// The raster's texels hold the field at their centres, and their bends are counted; those of column 0 hold no
// data, for the gaps.
std::shared_ptr<BlockRanges> countField(const Raster& raster, const Projection& projection) {
  auto blocks = std::make_shared<BlockRanges>(raster.width, raster.height,
                                              BlockRanges::blockTexelsFor(raster.width, raster.height));
  const std::array<double, 6>& t = raster.geotransform;
  std::vector<std::vector<double>> rows(std::size_t(raster.height),
                                        std::vector<double>(std::size_t(raster.width), std::nan("")));
  for (int row = 0; row < raster.height; ++row)
    for (int column = 1; column < raster.width; ++column) {
      const std::optional<glm::dvec2> lonlat =
          projection.inverse({t[0] + (column + 0.5) * t[1], t[3] + (row + 0.5) * t[5]});
      if (!lonlat) continue;
      blocks->count(column, row, field(*lonlat));
      rows[std::size_t(row)][std::size_t(column)] = field(*lonlat);
    }
  for (std::size_t row = 1; row + 1 < rows.size(); ++row)
    blocks->countBends(int(row), rows[row - 1], rows[row], rows[row + 1]);
  return blocks;
}

// A random direction within `angle` of `centre`.
glm::dvec3 inside(const SphericalCap& cap, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const glm::dvec3 helper = std::abs(cap.centre.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, cap.centre)), e2 = glm::cross(cap.centre, e1);
  const double angle = cap.angle * std::sqrt(unit(random)), turn = 2.0 * std::numbers::pi * unit(random);
  return std::cos(angle) * cap.centre + std::sin(angle) * (std::cos(turn) * e1 + std::sin(turn) * e2);
}

// Every point sampled in every cap: its texel's value lies in the cap's range, and a point off the raster
// or on its empty column finds gaps.
void expectHeld(const Raster& raster, const std::vector<SphericalCap>& caps) {
  std::shared_ptr<const Projection> projection = test::makeProjection(raster.terms, Ellipsoid{kEarth, 0.0});
  const std::shared_ptr<BlockRanges> ranges = countField(raster, *projection);
  const BlockCaps blockCaps(ranges, {projection, raster.geotransform}, raster.repeatX);
  std::mt19937 random(5);
  int sampled = 0;
  for (const SphericalCap& cap : caps) {
    const BlockValues values = blockCaps.within(cap);
    for (int i = 0; i < 300; ++i) {
      const std::optional<glm::dvec2> map = projection->forward(lonlatOf(inside(cap, random)));
      const glm::dvec2 texel = map ? texelOf(raster, *map) : glm::dvec2(-1.0);
      const int column = int(std::floor(texel.x)), row = int(std::floor(texel.y));
      if (column < 1 || row < 0 || column >= raster.width || row >= raster.height) {
        EXPECT_TRUE(values.gaps) << "a point of the cap lies off the raster";
        continue;
      }
      const std::optional<glm::dvec2> lonlat =
          projection->inverse({raster.geotransform[0] + (column + 0.5) * raster.geotransform[1],
                               raster.geotransform[3] + (row + 0.5) * raster.geotransform[5]});
      ASSERT_TRUE(lonlat);
      ++sampled;
      EXPECT_GE(field(*lonlat), values.least)
          << "cap at " << cap.centre.x << ", " << cap.centre.y << ", " << cap.centre.z;
      EXPECT_LE(field(*lonlat), values.greatest)
          << "cap at " << cap.centre.x << ", " << cap.centre.y << ", " << cap.centre.z;
    }
  }
  EXPECT_GT(sampled, 100 * int(caps.size()));
}

std::vector<SphericalCap> capsNear(glm::dvec2 lonlatDegrees, std::initializer_list<double> angles) {
  std::vector<SphericalCap> caps;
  for (const double angle : angles)
    caps.push_back({directionOf({radians(lonlatDegrees.x), radians(lonlatDegrees.y)}), angle});
  return caps;
}

TEST(BlockCaps, AGlobalMapHoldsEveryTexelACapSamplesAcrossItsSeamAndAtItsPoles) {
  const Raster global{"+proj=longlat", {-180.0, 0.25, 0.0, 90.0, 0.0, -0.25}, 1440, 720, true};
  for (const glm::dvec2 place : {glm::dvec2(137.4, -4.6), glm::dvec2(179.99, 10.0), glm::dvec2(-179.99, -30.0),
                                 glm::dvec2(0.0, 89.95), glm::dvec2(60.0, -89.95)})
    expectHeld(global, capsNear(place, {1e-4, 3e-3, 0.05, 0.6}));
}

// A grid whose texel centres lie on the poles and on the antimeridian (EGM96's 15' geoid: 1440 x 721), its
// edges half a texel beyond them, where no projection places a point: blocks along the poles are bounded by
// their texel centres, so a small cap far from them takes only its own blocks' values. When those blocks were
// taken to cover the whole body, every cap took the poles' values too, and an icosahedral patch under the
// geoid exaggerated 2000 times reached 116 km (EyeBelowTheGround).
TEST(BlockCaps, AGridCentredOnThePolesBoundsSmallCapsByTheirOwnBlocks) {
  const Raster grid{"+proj=longlat", {-180.125, 0.25, 0.0, 90.125, 0.0, -0.25}, 1440, 721, true};
  for (const glm::dvec2 place :
       {glm::dvec2(10.0, 20.0), glm::dvec2(179.99, 10.0), glm::dvec2(0.0, 89.99), glm::dvec2(60.0, -89.99)})
    expectHeld(grid, capsNear(place, {1e-4, 3e-3, 0.05}));
  std::shared_ptr<const Projection> projection = test::makeProjection(grid.terms, Ellipsoid{kEarth, 0.0});
  const BlockCaps blockCaps(countField(grid, *projection), {projection, grid.geotransform}, true);
  const BlockValues whole = blockCaps.within({glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi});
  const BlockValues near = blockCaps.within(capsNear({10.0, 20.0}, {1e-3})[0]);
  // The cap's blocks (8 texels, 2 degrees) reach some 0.06 rad from it, over which the field changes by 182 of
  // its whole range's 2,256 (0.08); with the poles' blocks everywhere, by 0.7 of it.
  EXPECT_LT(near.greatest - near.least, 0.15 * (whole.greatest - whole.least));
  EXPECT_FALSE(near.gaps);
}

// The relief of the finest blocks (BlockRelief): the whole body's query finds the largest range any one block
// holds, counted by brute force, and that block's width, its cap's diameter: at least a texel's quarter degree
// and at most a block's diagonal with its margins; a small cap's blocks hold no more relief than the cap's
// whole range.
TEST(BlockCaps, TheFinestBlocksReliefIsTheLargestOneBlockHolds) {
  const Raster grid{"+proj=longlat", {-180.125, 0.25, 0.0, 90.125, 0.0, -0.25}, 1440, 721, true};
  std::shared_ptr<const Projection> projection = test::makeProjection(grid.terms, Ellipsoid{kEarth, 0.0});
  const std::shared_ptr<BlockRanges> ranges = countField(grid, *projection);
  double largest = 0.0;
  for (int row = 0; row < ranges->rows(); ++row)
    for (int column = 0; column < ranges->columns(); ++column)
      if (const BlockRanges::Block& block = ranges->at(column, row); block.counted > 0)
        largest = std::max(largest, block.greatest - block.least);
  const BlockCaps blockCaps(ranges, {projection, grid.geotransform}, true);
  const BlockValues whole = blockCaps.within({glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi});
  EXPECT_DOUBLE_EQ(whole.blockRange, largest);
  const double blockDegrees = 0.25 * ranges->blockTexels();
  EXPECT_GT(whole.blockWidth, radians(0.25));
  EXPECT_LT(whole.blockWidth, radians(std::numbers::sqrt2 * (blockDegrees + 0.5) * 1.1));
  for (const SphericalCap& cap : capsNear({137.4, -4.6}, {1e-3, 0.05, 0.6})) {
    const BlockValues near = blockCaps.within(cap);
    EXPECT_GT(near.blockRange, 0.0);
    EXPECT_LE(near.blockRange, near.greatest - near.least);
  }
}

// The field's second derivative along the ground at `point` toward `heading` (rad from north), per rad squared:
// along the great circle, by central differences a microradian apart.
double secondDerivativeAlongTheGround(const glm::dvec3& point, double heading) {
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), point)), north = glm::cross(point, east);
  const glm::dvec3 toward = std::sin(heading) * east + std::cos(heading) * north;
  constexpr double step = 1e-4;
  const auto at = [&](double t) { return field(lonlatOf(std::cos(t) * point + std::sin(t) * toward)); };
  return (at(step) - 2.0 * at(0.0) + at(-step)) / (step * step);
}

// The curvature of the blocks within a cap (BlockValues::curvature, from their texels' bends) bounds the field's
// second derivative along the ground at every point and heading sampled in the cap, on a global
// longitude/latitude map far from longitude 0 and at 60 degrees, where its rows are half as long as its columns;
// it errs toward detail by the twist and by the ground the blocks cover beyond the cap: measured 1.12 to 1.38
// times the largest sampled, allowed 2. Caps over a pole, whose rows of texels span nothing, or over no
// data (column 0 holds none) know no curvature.
TEST(BlockCaps, TheBlocksCurvatureBoundsTheFieldsSecondDerivativeAlongTheGround) {
  const Raster global{"+proj=longlat", {-180.0, 0.25, 0.0, 90.0, 0.0, -0.25}, 1440, 720, true};
  std::shared_ptr<const Projection> projection = test::makeProjection(global.terms, Ellipsoid{kEarth, 0.0});
  const BlockCaps blockCaps(countField(global, *projection), {projection, global.geotransform}, true);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> heading(0.0, 2.0 * std::numbers::pi);
  for (const glm::dvec2 place : {glm::dvec2(137.4, -4.6), glm::dvec2(-100.0, 60.0)})
    for (const SphericalCap& cap : capsNear(place, {3e-3, 0.05})) {
      const BlockValues values = blockCaps.within(cap);
      ASSERT_TRUE(std::isfinite(values.curvature));
      double largest = 0.0;
      for (int i = 0; i < 300; ++i)
        largest = std::max(largest, std::abs(secondDerivativeAlongTheGround(inside(cap, random), heading(random))));
      std::printf("at %.1f, %.1f within %.3f rad: curvature %.0f, the largest sampled %.0f\n", place.x, place.y,
                  cap.angle, values.curvature, largest);
      EXPECT_GE(values.curvature, largest);
      EXPECT_LE(values.curvature, 2.0 * largest);
      EXPECT_NEAR(values.texel, radians(0.25), 1e-6);
    }
  EXPECT_TRUE(std::isinf(blockCaps.within(capsNear({20.0, 89.99}, {1e-3})[0]).curvature));
  EXPECT_TRUE(std::isinf(blockCaps.within(capsNear({-179.99, 10.0}, {1e-3})[0]).curvature));
}

TEST(BlockCaps, APolarStereographicMapHoldsEveryTexelACapSamples) {
  const Raster polar{
      "+proj=stere +lat_0=-90 +lat_ts=-71", {-3.0e6, 5000.0, 0.0, 3.0e6, 0.0, -5000.0}, 1200, 1200, false};
  for (const glm::dvec2 place : {glm::dvec2(0.0, -90.0), glm::dvec2(137.4, -70.0), glm::dvec2(-45.0, -62.0)})
    expectHeld(polar, capsNear(place, {1e-4, 5e-3, 0.1}));
}

// A map 2 by 1 degrees at 137.4 E: caps inside it are told they hold no gaps, and their ranges are those of
// their blocks, a share of the map's as small as their extent; caps across its edge or beyond it find gaps.
TEST(BlockCaps, ASmallMapTellsCapsInsideFromCapsAcrossItsEdge) {
  const Raster small{"+proj=longlat", {136.4, 0.001, 0.0, -4.1, 0.0, -0.001}, 2000, 1000, false};
  const std::vector<SphericalCap> caps = capsNear({137.4, -4.6}, {1e-5, 1e-3, 0.05});
  expectHeld(small, caps);
  expectHeld(small, capsNear({136.41, -4.6}, {1e-5, 1e-3}));
  std::shared_ptr<const Projection> projection = test::makeProjection(small.terms, Ellipsoid{kEarth, 0.0});
  const BlockCaps blockCaps(countField(small, *projection), {projection, small.geotransform}, false);
  const BlockValues whole = blockCaps.within(capsNear({137.4, -4.6}, {0.05})[0]);
  const BlockValues near = blockCaps.within(caps[1]);
  EXPECT_FALSE(near.gaps);
  // The cap is 2e-3 rad across and its blocks reach about 1e-3 rad beyond it: a tenth of the map's 0.035 rad
  // width, over which the field changes about evenly; a fifth leaves room for the blocks' corners.
  EXPECT_LT(near.greatest - near.least, 0.2 * (whole.greatest - whole.least));
  EXPECT_TRUE(whole.gaps) << "a cap of 0.05 rad reaches beyond a map 0.017 rad high";
  EXPECT_TRUE(blockCaps.within(capsNear({136.41, -4.6}, {1e-5})[0]).gaps) << "the empty first column";
  const BlockValues beyond = blockCaps.within(capsNear({140.0, -4.6}, {1e-3})[0]);
  EXPECT_TRUE(beyond.gaps);
  EXPECT_FALSE(beyond.counted());
}

// A HEALPix pyramid's strip of faces bounded by its stored page ranges (core/layers/src/healpix_page_caps.cpp),
// as an icosahedral patch over it asks them: every texel a cap's points sample lies in the cap's range, across
// the faces' edges (where the strip puts faces side by side that do not meet on the body) and at the poles,
// and caps over face 4, which holds no data, find gaps. The values rise from south to north, so that a cap's
// range shows where its pages lie.
TEST(BlockCaps, AHealpixStripsPageRangesHoldEveryTexelACapSamples) {
  constexpr int kNside = 1024;
  const std::shared_ptr<const Projection> strip =
      healpix::stripProjection(test::makeProjection("+proj=healpix", Ellipsoid{kEarth, 0.0}));
  const std::array<double, 6> t = healpix::stripGeotransform(kNside);
  const int pagesAcross = 12 * kNside / kPagePayload;
  const auto valueAt = [&](glm::ivec2 texel) -> std::optional<double> {
    if (texel.x / kNside == 4) return std::nullopt;  // face 4 holds no data
    return 500.0 * strip->inverse({t[0] + (texel.x + 0.5) * t[1], t[3] + (texel.y + 0.5) * t[5]})->y;
  };
  std::vector<healpix::PageRanges::Range> finest(std::size_t(pagesAcross) * (kNside / kPagePayload),
                                                 {INFINITY, -INFINITY, false});
  for (int row = 0; row < kNside; ++row)
    for (int column = 0; column < 12 * kNside; ++column) {
      healpix::PageRanges::Range& page = finest[std::size_t(row / kPagePayload) * pagesAcross + column / kPagePayload];
      const std::optional<double> value = valueAt({column, row});
      page = value ? healpix::PageRanges::Range{std::min(page.least, float(*value)),
                                                std::max(page.greatest, float(*value)), page.uncovered}
                   : healpix::PageRanges::Range{page.least, page.greatest, true};
    }
  const std::shared_ptr<const BlockCaps> caps = pageCapsOf(healpix::PageRanges(kNside, finest), {strip, t}, kNside);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int sampled = 0;
  for (int i = 0; i < 60; ++i) {
    const glm::dvec3 centre = glm::normalize(glm::dvec3(unit(random), unit(random), unit(random)));
    const SphericalCap cap{centre, std::array{1e-4, 3e-3, 0.05}[i % 3]};
    const BlockValues values = caps->within(cap);
    for (int j = 0; j < 100; ++j) {
      const glm::dvec2 map = *strip->forward(lonlatOf(inside(cap, random)));
      const glm::ivec2 texel(glm::floor(glm::dvec2((map.x - t[0]) / t[1], (map.y - t[3]) / t[5])));
      const std::optional<double> value =
          valueAt(glm::clamp(texel, glm::ivec2(0), glm::ivec2(12 * kNside - 1, kNside - 1)));
      if (!value) {
        EXPECT_TRUE(values.gaps) << "a point of the cap lies on the face without data";
        continue;
      }
      ++sampled;
      EXPECT_GE(float(*value), values.least) << "cap at " << centre.x << ", " << centre.y << ", " << centre.z;
      EXPECT_LE(float(*value), values.greatest) << "cap at " << centre.x << ", " << centre.y << ", " << centre.z;
    }
  }
  EXPECT_GT(sampled, 4000);
  // At nside 1024 a page is a quarter of a face, its stored range its eight neighbours' too: a small cap in
  // the far south takes no value of the northern hemisphere, the whole body all of them.
  const BlockValues south = caps->within({directionOf({radians(137.4), radians(-80.0)}), 1e-4});
  const BlockValues whole = caps->within({glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi});
  EXPECT_FALSE(south.gaps);
  EXPECT_LT(south.greatest, 0.0);
  EXPECT_TRUE(whole.gaps);
  EXPECT_GT(whole.greatest, 700.0);
}

}  // namespace
}  // namespace strata
