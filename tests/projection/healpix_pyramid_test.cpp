// The layout of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp): the strip's projection against the HEALPix
// grid (strata/plugin/healpix.hpp, itself checked against chealpix and PROJ in healpix_grid_test.cpp), its texels
// against chealpix's NESTED pixel centres, and the texels across each face's edges. Tolerance 1e-12 (radians,
// strip units) as in healpix_grid_test.cpp: the formulas lose a few units of 2^-53, so 1e-12 leaves room for
// no error of substance.
#include <gtest/gtest.h>

#include <chealpix.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <strata/plugin/healpix.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

#include "projection_cases.hpp"

namespace strata::healpix {
namespace {

constexpr double kTolerance = 1e-12;
const Ellipsoid kEarth{6378137.0, 298.257223563};

std::unique_ptr<Projection> strip(const Ellipsoid& ellipsoid) {
  return stripProjection(test::makeProjection("+proj=healpix", ellipsoid));
}

glm::dvec3 vectorOf(glm::dvec2 lonlat) {
  return {std::cos(lonlat.y) * std::cos(lonlat.x), std::cos(lonlat.y) * std::sin(lonlat.x), std::sin(lonlat.y)};
}

glm::dvec2 randomLonlat(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return {std::numbers::pi * (2.0 * unit(random) - 1.0), std::asin(2.0 * unit(random) - 1.0)};
}

// The bits of `a` in the even positions and those of `b` in the odd ones.
std::int64_t interleave(std::int64_t a, std::int64_t b) {
  std::int64_t bits = 0;
  for (int i = 0; i < 31; ++i) bits |= ((a >> i) & 1) << (2 * i) | ((b >> i) & 1) << (2 * i + 1);
  return bits;
}

TEST(HealpixPyramid, StripCoordinatesAreTheFacePoint) {
  const auto projection = strip(test::kMars);
  std::mt19937_64 random(6);
  for (int i = 0; i < 100000; ++i) {
    const glm::dvec2 lonlat = randomLonlat(random);
    const FacePoint expected = facePoint(lonlat);
    const glm::dvec2 xy = *projection->forward(lonlat);
    ASSERT_NEAR(xy.x, expected.face + expected.x, kTolerance);
    ASSERT_NEAR(xy.y, expected.y, kTolerance);
    ASSERT_LE(glm::length(vectorOf(*projection->inverse(xy)) - vectorOf(lonlat)), kTolerance);
  }
  EXPECT_FALSE(projection->inverse({12.5, 0.5}));
  EXPECT_FALSE(projection->inverse({3.0, 1.5}));
}

// On an ellipsoid the faces are those of the authalic latitude, as PROJ's healpix maps them: forward and
// inverse agree.
TEST(HealpixPyramid, StripRoundTripsOnAnEllipsoid) {
  const auto projection = strip(kEarth);
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec2 lonlat = randomLonlat(random);
    ASSERT_LE(glm::length(vectorOf(*projection->inverse(*projection->forward(lonlat))) - vectorOf(lonlat)), kTolerance);
  }
}

// Texel (column, row) of face f is chealpix's NESTED pixel f nside^2 + interleave(column, nside - 1 - row):
// the strip's geotransform and projection put the texel's centre on the pixel's centre.
TEST(HealpixPyramid, TexelCentresAreNestedPixelCentres) {
  const auto projection = strip(test::kMars);
  std::mt19937_64 random(8);
  for (const std::int64_t nside : {std::int64_t{512}, std::int64_t{1} << 20}) {
    const std::array<double, 6> t = stripGeotransform(nside);
    std::uniform_int_distribution<std::int64_t> texel(0, nside - 1);
    for (int i = 0; i < 20000; ++i) {
      const int face = i % 12;
      const std::int64_t column = texel(random), row = texel(random);
      const glm::dvec2 map(t[0] + (double(face * nside + column) + 0.5) * t[1], t[3] + (double(row) + 0.5) * t[5]);
      double theta = 0.0, phi = 0.0;
      pix2ang_nest64(nside, face * nside * nside + interleave(column, nside - 1 - row), &theta, &phi);
      const glm::dvec3 expected(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      ASSERT_LE(glm::length(vectorOf(*projection->inverse(map)) - expected), kTolerance)
          << "nside " << nside << " face " << face << " texel " << column << ", " << row;
    }
  }
}

TEST(HealpixPyramid, PagesStopAtFacesOfOnePage) {
  EXPECT_EQ(stripPyramid(512).levels(), 1);
  const PagePyramid pyramid = stripPyramid(4096);
  EXPECT_EQ(pyramid.levels(), 4);
  EXPECT_EQ(pyramid.pagesAcross(3), 12);
  EXPECT_EQ(pyramid.pagesDown(3), 1);
}

// The centre of a face texel, as a unit vector.
glm::dvec3 texelCentre(int side, glm::ivec2 texel) {
  const int face = texel.x / side;
  return unitVector({face, (texel.x - face * side + 0.5) / side, 1.0 - (texel.y + 0.5) / side});
}

// Every texel one beyond a face's edge is the neighbouring face's pixel across that edge: on another face,
// as far from the texel inside as the texel's neighbours inside the face are (the pixels share an edge),
// and across the edge from it in turn.
TEST(HealpixPyramid, TexelsAcrossFaceEdgesAreTheNeighbouringPixels) {
  for (const int side : {1, 2, 8, 512}) {
    for (int face = 0; face < 12; ++face)
      for (int k = 0; k < side; ++k)
        for (const auto& [outside, inside] : {std::pair{glm::ivec2(-1, k), glm::ivec2(0, k)},
                                              {glm::ivec2(side, k), glm::ivec2(side - 1, k)},
                                              {glm::ivec2(k, -1), glm::ivec2(k, 0)},
                                              {glm::ivec2(k, side), glm::ivec2(k, side - 1)}}) {
          const glm::ivec2 offset(face * side, 0);
          const glm::ivec2 across = texelAcross(side, face, outside + offset);
          const int neighbour = across.x / side;
          ASSERT_NE(neighbour, face);
          const double spacing = std::acos(-1.0) / 3.0 / side;  // about a pixel's width, sqrt(4 pi / 12) / side
          const double distance = glm::length(texelCentre(side, across) - texelCentre(side, inside + offset));
          ASSERT_GT(distance, 0.5 * spacing) << "side " << side << " face " << face;
          ASSERT_LT(distance, 1.6 * spacing) << "side " << side << " face " << face;
          bool returns = false;
          for (const glm::ivec2 step : {glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)}) {
            const glm::ivec2 beyond = across + step, local = beyond - glm::ivec2(neighbour * side, 0);
            if (local.x >= 0 && local.x < side && local.y >= 0 && local.y < side) continue;
            returns = returns || texelAcross(side, neighbour, beyond) == inside + offset;
          }
          ASSERT_TRUE(returns) << "side " << side << " face " << face << " texel " << inside.x << ", " << inside.y;
        }
  }
}

// Page ranges of a pyramid of `nside` whose level-0 page i holds the single value i, page 5 some texels of no data.
std::vector<PageRanges::Range> numberedPages(std::int64_t nside) {
  const std::int64_t pages = 12 * (nside / 512) * (nside / 512);
  std::vector<PageRanges::Range> finest;
  for (std::int64_t i = 0; i < pages; ++i) finest.push_back({float(i), float(i), i == 5});
  return finest;
}

bool holds(const PageRanges::Range& range, float value) { return range.least <= value && value <= range.greatest; }

// The unit vector of the centre of level-0 page (column, row) of a pyramid of nside 1024 (two pages a face side).
glm::dvec3 pageCentre(glm::ivec2 page) {
  const int face = page.x / 2;
  return unitVector({face, (page.x - 2 * face + 0.5) / 2.0, 1.0 - (page.y + 0.5) / 2.0});
}

// Each level-0 page holds its centre's angle from one page's centre: that page's node ranges hold the angles of
// it and its eight neighbours (across face edges too), and none of the pages far away.
TEST(HealpixPageRanges, BoundANodesPageAndItsNeighbours) {
  for (int face = 0; face < 12; ++face) {
    const glm::ivec2 page(face * 2 + 1, 0);  // x high, y high in the face
    std::vector<PageRanges::Range> finest;
    for (int row = 0; row < 2; ++row)
      for (int column = 0; column < 24; ++column) {
        const float angle =
            float(std::acos(std::clamp(glm::dot(pageCentre({column, row}), pageCentre(page)), -1.0, 1.0)));
        finest.push_back({angle, angle, false});
      }
    const PageRanges ranges(1024, finest);
    for (int level : {1, 4}) {
      const std::int64_t last = (std::int64_t{1} << level) - 1;
      const PageRanges::Range range = ranges.overNode(face, level, last, last);
      const auto angleOf = [&](glm::ivec2 p) { return finest[std::size_t(p.y * 24 + p.x)].least; };
      for (const glm::ivec2 neighbour :
           {page, page - glm::ivec2(1, 0), page + glm::ivec2(0, 1), page - glm::ivec2(1, -1)})
        EXPECT_TRUE(holds(range, angleOf(neighbour))) << "face " << face;
      for (const glm::ivec2 beyond : {page + glm::ivec2(1, 0), page - glm::ivec2(0, 1), page + glm::ivec2(1, -1)})
        EXPECT_TRUE(holds(range, angleOf(texelAcross(2, face, beyond)))) << "face " << face;
      EXPECT_LT(range.greatest, 1.3f) << "face " << face;  // a page is about half a radian across
    }
  }
}

// Face 0's whole-face node holds its own four pages, and knows of the texels of no data on face 2's page 5,
// which touches it at the pole.
TEST(HealpixPageRanges, AFaceHoldsItsPagesAndWhatTouchesIt) {
  const PageRanges ranges(1024, numberedPages(1024));
  const PageRanges::Range whole = ranges.overNode(0, 0, 0, 0);
  for (const float value : {0.0f, 1.0f, 24.0f, 25.0f}) EXPECT_TRUE(holds(whole, value));
  EXPECT_TRUE(whole.uncovered);
  EXPECT_FALSE(ranges.overNode(8, 0, 0, 0).uncovered);  // face 8 lies far from page 5
}

TEST(HealpixPageRanges, SurviveTheFilesMetadata) {
  for (const std::int64_t nside : {std::int64_t{1024}, std::int64_t{512} << 7}) {
    const PageRanges ranges(nside, numberedPages(nside));
    std::map<std::string, std::string> items;
    for (const auto& [name, value] : ranges.metadataItems()) items[name] = value;
    EXPECT_EQ(items.size(), nside == 1024 ? 2u : 7u) << "levels with at most kMostStoredPages pages";
    const std::optional<PageRanges> read = PageRanges::fromMetadata(
        nside, [&](const std::string& name) { return items.contains(name) ? items.at(name).c_str() : nullptr; });
    ASSERT_TRUE(read);
    for (int level = 0; level < 10; ++level)
      for (const std::int64_t i : {std::int64_t{0}, (std::int64_t{1} << level) - 1}) {
        const PageRanges::Range a = ranges.overNode(7, level, i, 0), b = read->overNode(7, level, i, 0);
        ASSERT_EQ(a.least, b.least);
        ASSERT_EQ(a.greatest, b.greatest);
        ASSERT_EQ(a.uncovered, b.uncovered);
      }
    EXPECT_FALSE(PageRanges::fromMetadata(2 * nside, [&](const std::string& name) {
      return items.contains(name) ? items.at(name).c_str() : nullptr;
    })) << "ranges of another nside";
  }
}

}  // namespace
}  // namespace strata::healpix
