#include "radial_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace strata::bdam {
namespace {

// Triangles (or edges) a cell of a grid on average: few, so that finding one is quick.
constexpr double kPerCell = 2.0;
// A triangle seen this nearly edge-on from the centre (the cosine of its normal's angle to the line) is left out.
constexpr double kEdgeOn = 1e-3;
// How far outside every triangle, in barycentric terms, a line may pass and still be measured (rounding at edges).
constexpr double kBeyondEdge = 1e-6;

double cross(glm::dvec2 x, glm::dvec2 y) { return x.x * y.y - x.y * y.x; }

// The least of a point's three barycentrics in a triangle: >= 0 inside it.
double leastBarycentric(const glm::dvec2& p, const std::array<glm::dvec2, 3>& t) {
  const double area = cross(t[1] - t[0], t[2] - t[0]);
  if (area == 0.0) return -std::numeric_limits<double>::infinity();
  return std::min(
      {cross(t[1] - p, t[2] - p) / area, cross(t[2] - p, t[0] - p) / area, cross(t[0] - p, t[1] - p) / area});
}

}  // namespace

void PlanetMesh::append(const PlanetMesh& other) {
  const auto base = std::uint32_t(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

PlanetMesh meshOf(const DisplacedTriangle& triangle, const DisplacedPatch& patch) {
  PlanetMesh mesh;
  for (const DisplacedVertex& v : patch.vertices) mesh.positions.push_back(triangle.point(v));
  mesh.indices = patch.indices;
  return mesh;
}

RadialSurface::RadialSurface(const DisplacedTriangle& node, const PlanetMesh& mesh)
    : origin_(node.corners[0]),
      normal_(glm::normalize(glm::cross(node.corners[1] - origin_, node.corners[2] - origin_))),
      u_(glm::normalize(node.corners[1] - origin_)),
      v_(glm::cross(normal_, u_)),
      vertices_(mesh.positions) {
  for (const glm::dvec3& p : vertices_) flatVertices_.push_back(projected(p));
  std::vector<std::array<std::uint32_t, 3>> kept;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> i = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const glm::dvec3 a = vertices_.at(i[0]), n = glm::cross(vertices_.at(i[1]) - a, vertices_.at(i[2]) - a);
    if (std::abs(glm::dot(n, glm::normalize(a))) <= kEdgeOn * glm::length(n)) continue;  // seen edge-on
    kept.push_back(i);
    facets_.push_back({{flatVertices_[i[0]], flatVertices_[i[1]], flatVertices_[i[2]]}, n, glm::dot(n, a)});
    for (std::size_t e = 0; e < 3; ++e)
      edges_.push_back({std::min(i[e], i[(e + 1) % 3]), std::max(i[e], i[(e + 1) % 3])});
  }
  if (facets_.empty()) throw std::invalid_argument("a surface without a triangle facing the body's centre");
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  low_ = high_ = facets_[0].corners[0];
  for (const Facet& f : facets_)
    for (const glm::dvec2& p : f.corners) low_ = glm::min(low_, p), high_ = glm::max(high_, p);
  facetGrid_.side = std::clamp(int(std::sqrt(double(facets_.size()) / kPerCell)), 1, 1024);
  facetGrid_.cells.resize(std::size_t(facetGrid_.side * facetGrid_.side));
  for (std::size_t f = 0; f < facets_.size(); ++f) {
    const auto& c = facets_[f].corners;
    list(facetGrid_, std::uint32_t(f), glm::min(c[0], glm::min(c[1], c[2])), glm::max(c[0], glm::max(c[1], c[2])));
  }
  edgeGrid_.side = std::clamp(int(std::sqrt(double(edges_.size()) / kPerCell)), 1, 1024);
  edgeGrid_.cells.resize(std::size_t(edgeGrid_.side * edgeGrid_.side));
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const glm::dvec2 a = flatVertices_[edges_[e][0]], b = flatVertices_[edges_[e][1]];
    list(edgeGrid_, std::uint32_t(e), glm::min(a, b), glm::max(a, b));
  }
}

void RadialSurface::list(Grid& grid, std::uint32_t item, const glm::dvec2& low, const glm::dvec2& high) const {
  const glm::ivec2 from = cellOf(low, grid.side), to = cellOf(high, grid.side);
  for (int y = from.y; y <= to.y; ++y)
    for (int x = from.x; x <= to.x; ++x) grid.cells[std::size_t(y * grid.side + x)].push_back(item);
}

bool RadialSurface::seenOnTheSamePlaneAs(const RadialSurface& other) const {
  return origin_ == other.origin_ && normal_ == other.normal_;
}

glm::ivec2 RadialSurface::cellOf(const glm::dvec2& onPlane, int side) const {
  const glm::dvec2 f = (onPlane - low_) / glm::max(high_ - low_, glm::dvec2(1e-300)) * double(side);
  return glm::ivec2(glm::clamp(glm::floor(f), glm::dvec2(0.0), glm::dvec2(side - 1)));  // in range before it is an int
}

glm::dvec2 RadialSurface::projected(const glm::dvec3& point) const {
  const glm::dvec3 onPlane = point * (glm::dot(normal_, origin_) / glm::dot(normal_, point)) - origin_;
  return {glm::dot(onPlane, u_), glm::dot(onPlane, v_)};
}

glm::dvec3 RadialSurface::direction(const glm::dvec2& onPlane) const {
  return glm::normalize(origin_ + onPlane.x * u_ + onPlane.y * v_);
}

std::optional<double> RadialSurface::radiusAlong(const glm::dvec3& direction) const {
  const glm::dvec2 p = projected(direction);
  const glm::ivec2 cell = cellOf(p, facetGrid_.side);
  const Facet* best = nullptr;
  double bestInside = -std::numeric_limits<double>::infinity();
  for (std::uint32_t f : facetGrid_.cells[std::size_t(cell.y * facetGrid_.side + cell.x)]) {
    const double inside = leastBarycentric(p, facets_[f].corners);
    if (inside > bestInside) best = &facets_[f], bestInside = inside;
  }
  if (!best || bestInside < -kBeyondEdge) return std::nullopt;
  return best->offset / glm::dot(best->normal, direction);
}

std::vector<glm::dvec3> RadialSurface::vertexDirections() const {
  std::vector<glm::dvec3> directions;
  for (const glm::dvec3& p : vertices_) directions.push_back(glm::normalize(p));
  return directions;
}

std::vector<glm::dvec3> RadialSurface::crossingDirections(const RadialSurface& other) const {
  std::vector<glm::dvec3> directions;
  std::vector<std::uint32_t> seen(other.edges_.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    const glm::dvec2 a = flatVertices_[edges_[e][0]], b = flatVertices_[edges_[e][1]];
    const glm::ivec2 from = other.cellOf(glm::min(a, b), other.edgeGrid_.side);
    const glm::ivec2 to = other.cellOf(glm::max(a, b), other.edgeGrid_.side);
    for (int y = from.y; y <= to.y; ++y)
      for (int x = from.x; x <= to.x; ++x)
        for (std::uint32_t o : other.edgeGrid_.cells[std::size_t(y * other.edgeGrid_.side + x)]) {
          if (seen[o] == e) continue;
          seen[o] = e;
          const glm::dvec2 c = other.flatVertices_[other.edges_[o][0]], d = other.flatVertices_[other.edges_[o][1]];
          const double denominator = cross(b - a, d - c);  // a + s (b - a) = c + r (d - c), within both
          if (denominator == 0.0) continue;
          const double s = cross(c - a, d - c) / denominator, r = cross(c - a, b - a) / denominator;
          if (s > 0.0 && s < 1.0 && r > 0.0 && r < 1.0) directions.push_back(direction(a + s * (b - a)));
        }
  }
  return directions;
}

double radialDeviation(const RadialSurface& coarse, const RadialSurface& fine) {
  if (!coarse.seenOnTheSamePlaneAs(fine)) throw std::invalid_argument("surfaces compared on different planes");
  double deviation = 0.0;
  for (const auto& directions : {coarse.vertexDirections(), fine.vertexDirections(), coarse.crossingDirections(fine)})
    for (const glm::dvec3& d : directions) {
      const std::optional<double> a = coarse.radiusAlong(d), b = fine.radiusAlong(d);
      if (a && b) deviation = std::max(deviation, std::abs(*a - *b));
    }
  return deviation;
}

double radialDeviation(const RadialSurface& surface, std::span<const glm::dvec3> points) {
  double deviation = 0.0;
  for (const glm::dvec3& point : points)
    if (const std::optional<double> r = surface.radiusAlong(glm::normalize(point)))
      deviation = std::max(deviation, std::abs(*r - glm::length(point)));
  return deviation;
}

}  // namespace strata::bdam
