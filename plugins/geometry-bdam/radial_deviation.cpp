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

// The least of a point's three barycentrics in a triangle, given the inverse of its doubled area: >= 0 inside it.
double leastBarycentric(const glm::dvec2& p, const std::array<glm::dvec2, 3>& t, double inverseArea) {
  if (inverseArea == 0.0) return -std::numeric_limits<double>::infinity();
  return std::min({inverseArea * cross(t[1] - p, t[2] - p), inverseArea * cross(t[2] - p, t[0] - p),
                   inverseArea * cross(t[0] - p, t[1] - p)});
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
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> i = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const glm::dvec3 a = vertices_.at(i[0]), n = glm::cross(vertices_.at(i[1]) - a, vertices_.at(i[2]) - a);
    if (std::abs(glm::dot(n, glm::normalize(a))) <= kEdgeOn * glm::length(n)) continue;  // seen edge-on
    const std::array<glm::dvec2, 3> corners = {flatVertices_[i[0]], flatVertices_[i[1]], flatVertices_[i[2]]};
    const double area = cross(corners[1] - corners[0], corners[2] - corners[0]);
    facets_.push_back({corners, area != 0.0 ? 1.0 / area : 0.0, n, glm::dot(n, a)});
    for (std::size_t e = 0; e < 3; ++e)
      edges_.push_back({std::min(i[e], i[(e + 1) % 3]), std::max(i[e], i[(e + 1) % 3])});
  }
  if (facets_.empty()) throw std::invalid_argument("a surface without a triangle facing the body's centre");
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  low_ = high_ = facets_[0].corners[0];
  for (const Facet& f : facets_)
    for (const glm::dvec2& p : f.corners) low_ = glm::min(low_, p), high_ = glm::max(high_, p);
  std::vector<Bounds> bounds;
  for (const Facet& f : facets_) {
    const auto& c = f.corners;
    bounds.emplace_back(glm::min(c[0], glm::min(c[1], c[2])), glm::max(c[0], glm::max(c[1], c[2])));
  }
  facetGrid_ = gridOver(bounds);
  bounds.clear();
  for (const auto& [a, b] : edges_)
    bounds.emplace_back(glm::min(flatVertices_[a], flatVertices_[b]), glm::max(flatVertices_[a], flatVertices_[b]));
  edgeGrid_ = gridOver(bounds);
}

// A grid of about kPerCell items a cell, listing each item in every cell its bounds touch.
RadialSurface::Grid RadialSurface::gridOver(const std::vector<Bounds>& bounds) const {
  Grid grid;
  grid.side = std::clamp(int(std::sqrt(double(bounds.size()) / kPerCell)), 1, 1024);
  grid.scale = double(grid.side) / glm::max(high_ - low_, glm::dvec2(1e-300));
  const auto cells = std::size_t(grid.side * grid.side);
  grid.first.assign(cells + 1, 0);
  const auto eachCell = [&](const Bounds& b, const auto& visit) {
    const glm::ivec2 from = cellOf(b.first, grid), to = cellOf(b.second, grid);
    for (int y = from.y; y <= to.y; ++y)
      for (int x = from.x; x <= to.x; ++x) visit(std::size_t(y * grid.side + x));
  };
  for (const Bounds& b : bounds) eachCell(b, [&](std::size_t c) { ++grid.first[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) grid.first[c + 1] += grid.first[c];
  grid.items.resize(grid.first[cells]);
  std::vector<std::uint32_t> filled(grid.first.begin(), grid.first.end() - 1);
  for (std::size_t i = 0; i < bounds.size(); ++i)
    eachCell(bounds[i], [&](std::size_t c) { grid.items[filled[c]++] = std::uint32_t(i); });
  return grid;
}

bool RadialSurface::seenOnTheSamePlaneAs(const RadialSurface& other) const {
  return origin_ == other.origin_ && normal_ == other.normal_;
}

glm::ivec2 RadialSurface::cellOf(const glm::dvec2& onPlane, const Grid& grid) const {
  const auto along = [last = double(grid.side - 1)](double cells) {
    return int(std::max(0.0, std::min(cells, last)));  // in range (NaN to 0) before it is an int, which truncates
  };
  return {along((onPlane.x - low_.x) * grid.scale.x), along((onPlane.y - low_.y) * grid.scale.y)};
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
  const Facet* best = nullptr;
  double bestInside = -std::numeric_limits<double>::infinity();
  for (std::uint32_t f : facetGrid_.in(cellOf(p, facetGrid_))) {
    const Facet& facet = facets_[f];
    const double inside = leastBarycentric(p, facet.corners, facet.inverseArea);
    if (inside > bestInside) best = &facet, bestInside = inside;
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
    const glm::ivec2 from = other.cellOf(glm::min(a, b), other.edgeGrid_);
    const glm::ivec2 to = other.cellOf(glm::max(a, b), other.edgeGrid_);
    for (int y = from.y; y <= to.y; ++y)
      for (int x = from.x; x <= to.x; ++x)
        for (std::uint32_t o : other.edgeGrid_.in({x, y})) {
          if (seen[o] == e) continue;
          seen[o] = e;
          const glm::dvec2 c = other.flatVertices_[other.edges_[o][0]], d = other.flatVertices_[other.edges_[o][1]];
          const double denominator = cross(b - a, d - c);  // a + s (b - a) = c + r (d - c), within both
          const double sTimes = cross(c - a, d - c), rTimes = cross(c - a, b - a);
          if (denominator == 0.0 || std::signbit(sTimes) != std::signbit(denominator) ||
              std::signbit(rTimes) != std::signbit(denominator))
            continue;  // s or r is not positive: most pairs, found without dividing
          const double s = sTimes / denominator, r = rTimes / denominator;
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
