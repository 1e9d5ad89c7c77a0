// geometry.bdam's partition of the planet: twelve bintrees on the equi-angular cube. Every level tiles the sphere
// (its spherical triangles' areas sum to 4 pi, each point of the body in one leaf), edges two faces share map to the
// same bits from either face, every node meets exactly one node of its level across its hypotenuse (on its face or
// the next), children halve their parent, and the cells are alike in area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <tuple>
#include <vector>

#include "cube_bintree.hpp"

namespace strata::bdam {
namespace {

std::vector<BintreeNode> nodesOfLevel(int level) {
  std::vector<BintreeNode> nodes;
  for (int root = 0; root < kBintreeRoots; ++root) nodes.push_back({root, 0, 0});
  for (int l = 0; l < level; ++l) {
    std::vector<BintreeNode> finer;
    for (const BintreeNode& node : nodes)
      for (const BintreeNode& child : children(node)) finer.push_back(child);
    nodes.swap(finer);
  }
  return nodes;
}

std::array<glm::dvec3, 3> corners(const BintreeNode& node) {
  const FaceTriangle triangle = faceTriangle(node);
  const int face = faceOf(node);
  return {cubeDirection(face, triangle.apex), cubeDirection(face, triangle.left), cubeDirection(face, triangle.right)};
}

// The spherical triangle's area (Van Oosterom and Strackee): its solid angle.
double sphericalArea(const std::array<glm::dvec3, 3>& c) {
  const double numerator = glm::dot(c[0], glm::cross(c[1], c[2]));
  const double denominator = 1.0 + glm::dot(c[0], c[1]) + glm::dot(c[1], c[2]) + glm::dot(c[2], c[0]);
  return 2.0 * std::atan2(numerator, denominator);
}

using Point = std::tuple<double, double, double>;
Point key(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

TEST(CubeBintree, EveryLevelTilesTheSphereCounterClockwise) {
  for (const int level : {0, 3, 8}) {
    double area = 0.0;
    for (const BintreeNode& node : nodesOfLevel(level)) {
      const double own = sphericalArea(corners(node));
      ASSERT_GT(own, 0.0) << "counter-clockwise from outside";
      area += own;
    }
    EXPECT_NEAR(area, 4.0 * std::numbers::pi, 1e-9) << "level " << level;
  }
}

TEST(CubeBintree, EdgesTwoFacesShareAreTheSameBitsFromEither) {
  std::map<Point, int> seen;  // each point of a face's rim, counted once per face that reaches it
  for (int face = 0; face < kCubeFaces; ++face)
    for (int k = 0; k <= 64; ++k) {
      const double along = -1.0 + k / 32.0;
      for (const glm::dvec2 st :
           {glm::dvec2(-1, along), glm::dvec2(1, along), glm::dvec2(along, -1), glm::dvec2(along, 1)})
        ++seen[key(cubeDirection(face, st))];
    }
  for (const auto& [point, faces] : seen) {
    const bool corner = std::abs(std::get<0>(point)) == std::abs(std::get<1>(point)) &&
                        std::abs(std::get<1>(point)) == std::abs(std::get<2>(point));
    // Rim points are met by two faces (each twice at a face's corner, from its two edges), cube corners by three.
    EXPECT_EQ(faces, corner ? 6 : 2) << std::get<0>(point) << ", " << std::get<1>(point) << ", " << std::get<2>(point);
  }
  EXPECT_EQ(seen.size(), 12u * 63u + 8u) << "12 edges' 63 inner points and 8 corners";
}

TEST(CubeBintree, EveryNodeMeetsOneOfItsLevelAcrossItsHypotenuse) {
  for (const int level : {0, 1, 5, 9}) {
    std::map<std::pair<Point, Point>, int> hypotenuses;
    for (const BintreeNode& node : nodesOfLevel(level)) {
      const std::array<glm::dvec3, 3> c = corners(node);
      hypotenuses[std::minmax(key(c[1]), key(c[2]))]++;
    }
    for (const auto& [ends, count] : hypotenuses) ASSERT_EQ(count, 2) << "level " << level;
    EXPECT_EQ(hypotenuses.size(), std::size_t(kBintreeRoots) << level >> 1) << "level " << level;
  }
}

TEST(CubeBintree, ChildrenHalveTheirParentAtItsHypotenusesMidpoint) {
  for (const BintreeNode& node : nodesOfLevel(4)) {
    const FaceTriangle parent = faceTriangle(node);
    const glm::dvec2 middle = 0.5 * (parent.left + parent.right);
    const auto [first, second] = children(node);
    const FaceTriangle a = faceTriangle(first), b = faceTriangle(second);
    EXPECT_EQ(a.apex, middle);
    EXPECT_EQ(b.apex, middle);
    EXPECT_EQ(a.left, parent.apex);
    EXPECT_EQ(a.right, parent.left);
    EXPECT_EQ(b.left, parent.right);
    EXPECT_EQ(b.right, parent.apex);
  }
}

// The equi-angular cube keeps cells alike: measured at level 10 (12,288 nodes), the largest 1.41 times the smallest.
TEST(CubeBintree, TheCellsAreAlikeInArea) {
  double smallest = 1e9, largest = 0.0;
  for (const BintreeNode& node : nodesOfLevel(10)) {
    const double area = sphericalArea(corners(node));
    smallest = std::min(smallest, area), largest = std::max(largest, area);
  }
  std::printf("level 10: the largest cell %.3f times the smallest\n", largest / smallest);
  EXPECT_LT(largest / smallest, 1.5);
}

// Face coordinates undo the warp, and the node found for a direction holds it, at places that matter: Gale crater,
// both sides of the antimeridian, the poles, a cube corner and edge, and a spread of others.
TEST(CubeBintree, TheNodeFoundForADirectionHoldsIt) {
  std::vector<glm::dvec3> directions = {
      glm::normalize(glm::dvec3(1, 1, 1)), glm::normalize(glm::dvec3(1, -1, 0)), {0, 0, 1}, {0, 0, -1}};
  for (const glm::dvec2 lonlat : {glm::dvec2(137.4, -4.6), glm::dvec2(179.9999, 12), glm::dvec2(-179.9999, 12),
                                  glm::dvec2(10, 20), glm::dvec2(-60, 89.99)}) {
    const glm::dvec2 r = glm::radians(lonlat);
    directions.push_back({std::cos(r.y) * std::cos(r.x), std::cos(r.y) * std::sin(r.x), std::sin(r.y)});
  }
  for (int k = 0; k < 200; ++k) {  // a Fibonacci spiral over the sphere
    const double z = 1.0 - (k + 0.5) / 100.0, around = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
    directions.push_back({std::sqrt(1.0 - z * z) * std::cos(around), std::sqrt(1.0 - z * z) * std::sin(around), z});
  }
  for (const glm::dvec3& direction : directions) {
    const FacePoint point = facePoint(direction);
    EXPECT_LT(glm::length(cubeDirection(point.face, point.coordinates) - direction), 1e-15);
    for (const int level : {0, 1, 7, 20, 40}) {
      const BintreeNode node = nodeContaining(direction, level);
      ASSERT_EQ(faceOf(node), point.face);
      const FaceTriangle t = faceTriangle(node);
      const auto inside = [&](glm::dvec2 a, glm::dvec2 b) {  // on the left of a to b, counter-clockwise, or on it
        const glm::dvec2 edge = b - a, to = point.coordinates - a;
        return edge.x * to.y - edge.y * to.x >= -1e-15 * glm::length(edge);
      };
      EXPECT_TRUE(inside(t.apex, t.left) && inside(t.left, t.right) && inside(t.right, t.apex))
          << direction.x << ", " << direction.y << ", " << direction.z << " at level " << level;
    }
  }
}

TEST(CubeBintree, ANodeBeyondTheTreesIsRefused) {
  EXPECT_THROW(faceTriangle({12, 0, 0}), std::invalid_argument);
  EXPECT_THROW(children({0, kDeepestLevel, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace strata::bdam
