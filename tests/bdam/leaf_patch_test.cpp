// geometry.bdam's leaf patches on real heights: EGM96's geoid (proj-data) exaggerated 100 times on Mars's radius,
// at Gale crater's place and by the north pole. Every vertex lies on the terrain, within the half centimetre its
// stored displacement rounds to; the patch holds divisions^2 triangles, counter-clockwise from outside.
#include <gtest/gtest.h>

#include <cmath>

#include "cube_bintree.hpp"
#include "displaced_triangle.hpp"
#include "leaf_patch.hpp"
#include "raster_heights.hpp"

namespace strata::bdam {
namespace {

constexpr double kMars = 3396190.0;  // m

glm::dvec3 direction(double lon, double lat) {
  const glm::dvec2 r = glm::radians(glm::dvec2(lon, lat));
  return {std::cos(r.y) * std::cos(r.x), std::cos(r.y) * std::sin(r.x), std::sin(r.y)};
}

TEST(LeafPatch, EveryVertexLiesOnTheTerrain) {
  const HeightAt geoid = RasterHeights("/usr/share/proj/egm96_15.gtx").sampler();
  const HeightAt heights = [&geoid](const glm::dvec3& d) { return 100.0 * geoid(d); };
  for (const glm::dvec3 place : {direction(137.4, -4.6), direction(30.0, 89.9)})
    for (const int level : {8, 16}) {  // triangles of about 330 and 21 km a side
      const BintreeNode node = nodeContaining(place, level);
      const DisplacedPatch patch = leafPatch(node, kMars, heights, 16);
      ASSERT_EQ(patch.indices.size(), 3u * 16 * 16);
      ASSERT_EQ(patch.vertices.size(), 17u * 18 / 2);
      const DisplacedTriangle triangle = displacedTriangle(node, kMars);
      for (const DisplacedVertex& vertex : patch.vertices) {
        const glm::dvec3 point = triangle.point(vertex);
        const double off = glm::length(point) - (kMars + heights(glm::normalize(point)));
        ASSERT_LT(std::abs(off), 0.006) << "m off the terrain, level " << level;
      }
      for (std::size_t i = 0; i < patch.indices.size(); i += 3) {
        const glm::dvec3 a = triangle.point(patch.vertices[patch.indices[i]]);
        const glm::dvec3 b = triangle.point(patch.vertices[patch.indices[i + 1]]);
        const glm::dvec3 c = triangle.point(patch.vertices[patch.indices[i + 2]]);
        ASSERT_GT(glm::dot(glm::cross(b - a, c - a), a), 0.0) << "counter-clockwise from outside";
      }
    }
}

}  // namespace
}  // namespace strata::bdam
