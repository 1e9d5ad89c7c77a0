#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "displaced_patch.hpp"
#include "displaced_triangle.hpp"

namespace strata::bdam {

// Triangles of planetocentric points, indexed.
struct PlanetMesh {
  std::vector<glm::dvec3> positions;  // m
  std::vector<std::uint32_t> indices;
  void append(const PlanetMesh& other);
};

// A patch's triangles as planetocentric points.
PlanetMesh meshOf(const DisplacedTriangle& triangle, const DisplacedPatch& patch);

// Triangles seen from the body's centre, found along the line through a direction. A triangle seen from the centre is
// a triangle on any plane in front of it, here the plane of a node's corners, where each line is found among them
// (in a grid of their bounds). Triangles seen nearly edge-on are left out: walls along a frozen edge, three of its
// vertices, which simplification can leave, cover no line.
class RadialSurface {
 public:
  RadialSurface(const DisplacedTriangle& node, const PlanetMesh& mesh);
  // The distance from the centre, m, at which the line through `direction` (unit) meets the surface; at a line
  // just beyond its edge (rounding), the nearest triangle's plane there; empty for a line well clear of it.
  std::optional<double> radiusAlong(const glm::dvec3& direction) const;
  // The directions of its vertices, and of the points where its edges cross `other`'s seen from the centre.
  std::vector<glm::dvec3> vertexDirections() const;
  std::vector<glm::dvec3> crossingDirections(const RadialSurface& other) const;
  bool seenOnTheSamePlaneAs(const RadialSurface& other) const;

 private:
  // A triangle on the plane, and its own plane in space: the line through d meets it at offset / (normal . d).
  struct Facet {
    std::array<glm::dvec2, 3> corners;
    double inverseArea;  // of its corners' triangle, doubled; 0 where that has none
    glm::dvec3 normal;
    double offset;
  };
  // A grid over the surface's bounds on the plane, each cell listing what touches it: cell c's items are
  // items[first[c]] up to items[first[c + 1]].
  struct Grid {
    int side = 1;
    glm::dvec2 scale{0.0};  // cells a metre on the plane
    std::vector<std::uint32_t> first, items;
    std::span<const std::uint32_t> in(const glm::ivec2& cell) const {
      const auto c = std::size_t(cell.y * side + cell.x);
      return std::span(items).subspan(first[c], first[c + 1] - first[c]);
    }
  };
  using Bounds = std::pair<glm::dvec2, glm::dvec2>;

  glm::dvec2 projected(const glm::dvec3& point) const;
  glm::dvec3 direction(const glm::dvec2& onPlane) const;
  glm::ivec2 cellOf(const glm::dvec2& onPlane, const Grid& grid) const;
  Grid gridOver(const std::vector<Bounds>& bounds) const;

  glm::dvec3 origin_, normal_, u_, v_;
  std::vector<glm::dvec2> flatVertices_;
  std::vector<glm::dvec3> vertices_;
  std::vector<Facet> facets_;
  std::vector<std::array<std::uint32_t, 2>> edges_;  // each once, by vertex
  glm::dvec2 low_{0.0}, high_{0.0};
  Grid facetGrid_, edgeGrid_;
};

// The object-space error of a coarse surface against a finer one, both seen on the same node's plane [Cignoni et al.
// 2003, §5: "the maximum difference from the original mesh in the planetocentric reference system (along the normal to
// the planet surface)"]: the largest distance along a line from the body's centre between the two, over the lines
// through either's vertices and their edges' crossings, where the largest of two triangulated surfaces' differences
// lies. The paper renders both from the centre and compares their depth buffers, which samples at its pixels.
double radialDeviation(const RadialSurface& coarse, const RadialSurface& fine);

// The largest distance along the line from the centre through each of `points` to `surface`.
double radialDeviation(const RadialSurface& surface, std::span<const glm::dvec3> points);

}  // namespace strata::bdam
