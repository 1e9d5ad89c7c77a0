// The object-space error geometry.bdam's build measures between two surfaces seen from the body's centre: a vertex
// raised by a known height is found, whichever way the triangles wind, and a surface against itself deviates by
// nothing. Gale crater's place on Mars, a patch of about 21 km a side.
#include <gtest/gtest.h>

#include <cmath>

#include "cube_bintree.hpp"
#include "displaced_triangle.hpp"
#include "leaf_patch.hpp"
#include "radial_deviation.hpp"

namespace strata::bdam {
namespace {

constexpr double kMars = 3396190.0;  // m
constexpr int kDivisions = 16;
// The error is a difference of radii of some 3.4e6 m found by intersecting planes in double: a few ulps of the radius.
constexpr double kTolerance = 1e-6;  // m

struct Surfaces {
  DisplacedTriangle triangle;
  PlanetMesh flat, raised;
};

// A leaf patch at 250 m above the sphere, and the same with its middle vertex `raise` m higher.
Surfaces withOneVertexRaised(double raise) {
  const glm::dvec2 gale = glm::radians(glm::dvec2(137.4, -4.6));
  const glm::dvec3 place(std::cos(gale.y) * std::cos(gale.x), std::cos(gale.y) * std::sin(gale.x), std::sin(gale.y));
  const BintreeNode node = nodeContaining(place, 16);
  Surfaces surfaces{displacedTriangle(node, kMars), {}, {}};
  surfaces.flat = meshOf(surfaces.triangle, leafPatch(
                                                node, kMars, [](const glm::dvec3&) { return 250.0; }, kDivisions));
  surfaces.raised = surfaces.flat;
  glm::dvec3& middle = surfaces.raised.positions[surfaces.raised.positions.size() / 2];
  middle *= (glm::length(middle) + raise) / glm::length(middle);
  return surfaces;
}

PlanetMesh clockwise(PlanetMesh mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  return mesh;
}

TEST(RadialDeviation, FindsARaisedVertex) {
  const Surfaces s = withOneVertexRaised(37.5);
  const RadialSurface flat(s.triangle, s.flat), raised(s.triangle, s.raised);
  EXPECT_NEAR(radialDeviation(flat, raised), 37.5, kTolerance);
  EXPECT_NEAR(radialDeviation(raised, flat), 37.5, kTolerance);
  EXPECT_NEAR(radialDeviation(flat, flat), 0.0, kTolerance);
  EXPECT_NEAR(radialDeviation(flat, s.raised.positions), 37.5, kTolerance);
}

TEST(RadialDeviation, WhicheverWayTheTrianglesWind) {
  const Surfaces s = withOneVertexRaised(-12.0);
  const RadialSurface flat(s.triangle, clockwise(s.flat)), raised(s.triangle, clockwise(s.raised));
  EXPECT_NEAR(radialDeviation(flat, raised), 12.0, kTolerance);
  EXPECT_NEAR(radialDeviation(flat, s.raised.positions), 12.0, kTolerance);
}

}  // namespace
}  // namespace strata::bdam
