// geometry.bdam's patches ordered for drawing: the same triangles, each with its winding, the vertices in the order
// the triangles first name them, fewer vertex cache misses than a shuffled patch's and a smaller stored patch.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>
#include <vector>

#include <meshoptimizer.h>

#include "leaf_patch.hpp"
#include "patch_codec.hpp"
#include "patch_order.hpp"

namespace strata::bdam {
namespace {

using Corner = std::tuple<int, int, int>;
using Triangle = std::array<Corner, 3>;

// The patch's triangles by their vertices' values, each rotated to start at its least corner (keeping its winding),
// sorted: equal for two patches that draw the same triangles.
std::vector<Triangle> trianglesOf(const DisplacedPatch& patch) {
  std::vector<Triangle> triangles;
  for (std::size_t i = 0; i < patch.indices.size(); i += 3) {
    Triangle t;
    for (std::size_t k = 0; k < 3; ++k) {
      const DisplacedVertex& v = patch.vertices[patch.indices[i + k]];
      t[k] = {v.b1, v.b2, v.centimetres};
    }
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

// The grid with its vertices and its triangles shuffled, and a vertex no triangle names.
DisplacedPatch shuffledGrid() {
  const DisplacedPatch grid = leafPatch(
      {3, 9, 0}, 3396190.0, [](const glm::dvec3& d) { return 3000.0 * std::sin(90.0 * d.z); }, 24);
  std::mt19937 random(2003);
  std::vector<std::uint32_t> newPlace(grid.vertices.size());
  for (std::uint32_t i = 0; i < newPlace.size(); ++i) newPlace[i] = i;
  std::shuffle(newPlace.begin(), newPlace.end(), random);
  DisplacedPatch shuffled{std::vector<DisplacedVertex>(grid.vertices.size()), {}};
  for (std::size_t i = 0; i < grid.vertices.size(); ++i) shuffled.vertices[newPlace[i]] = grid.vertices[i];
  shuffled.vertices.push_back({7, 7, 7});
  std::vector<std::size_t> order(grid.indices.size() / 3);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), random);
  for (const std::size_t t : order)
    for (std::size_t k = 0; k < 3; ++k) shuffled.indices.push_back(newPlace[grid.indices[3 * t + k]]);
  return shuffled;
}

double cacheMisses(const DisplacedPatch& patch) {  // per triangle, for a 16-entry FIFO cache
  return meshopt_analyzeVertexCache(patch.indices.data(), patch.indices.size(), patch.vertices.size(), 16, 0, 0).acmr;
}

TEST(PatchOrder, DrawsTheSameTrianglesFromVerticesInTheOrderTheyAreFirstNamed) {
  const DisplacedPatch shuffled = shuffledGrid();
  const DisplacedPatch ordered = orderedForDrawing(shuffled);
  EXPECT_EQ(trianglesOf(ordered), trianglesOf(shuffled));
  EXPECT_EQ(ordered.vertices.size(), shuffled.vertices.size() - 1) << "the vertex no triangle names is left out";
  std::uint32_t next = 0;
  for (const std::uint32_t index : ordered.indices) {
    ASSERT_LE(index, next) << "a vertex named before those before it";
    next = std::max(next, index + 1);
  }
  const double before = cacheMisses(shuffled), after = cacheMisses(ordered);
  const std::size_t storedBefore = encodePatch(shuffled).size(), storedAfter = encodePatch(ordered).size();
  std::printf("cache misses a triangle %.2f -> %.2f; stored %zu -> %zu bytes\n", before, after, storedBefore,
              storedAfter);
  EXPECT_LT(after, 0.75 * before);
  EXPECT_LT(storedAfter, storedBefore);
}

}  // namespace
}  // namespace strata::bdam
