#include "radial_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace strata::bdam {
namespace {

// Triangles a cell of the grid they are found in, on average: few, so that finding one is quick.
constexpr double kTrianglesPerCell = 2.0;
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

bool seenEdgeOn(const std::array<glm::dvec3, 3>& t) {
  const glm::dvec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
  return std::abs(glm::dot(normal, glm::normalize(t[0]))) <= kEdgeOn * glm::length(normal);
}

}  // namespace

RadialSurface::RadialSurface(const DisplacedTriangle& node, std::vector<std::array<glm::dvec3, 3>> triangles)
    : origin_(node.corners[0]),
      normal_(glm::normalize(glm::cross(node.corners[1] - origin_, node.corners[2] - origin_))),
      u_(glm::normalize(node.corners[1] - origin_)),
      v_(glm::cross(normal_, u_)) {
  std::erase_if(triangles, seenEdgeOn);
  if (triangles.empty()) throw std::invalid_argument("a surface without a triangle facing the body's centre");
  triangles_ = std::move(triangles);
  for (const auto& t : triangles_) flat_.push_back({projected(t[0]), projected(t[1]), projected(t[2])});
  uniqueVerticesAndEdges();
  low_ = high_ = flat_[0][0];
  for (const auto& t : flat_)
    for (const glm::dvec2& p : t) low_ = glm::min(low_, p), high_ = glm::max(high_, p);
  cellsASide_ = std::clamp(int(std::sqrt(double(flat_.size()) / kTrianglesPerCell)), 1, 1024);
  cells_.resize(std::size_t(cellsASide_ * cellsASide_));
  for (std::size_t i = 0; i < flat_.size(); ++i) {
    const auto& t = flat_[i];
    const glm::ivec2 from = cellOf(glm::min(t[0], glm::min(t[1], t[2]))),
                     to = cellOf(glm::max(t[0], glm::max(t[1], t[2])));
    for (int y = from.y; y <= to.y; ++y)
      for (int x = from.x; x <= to.x; ++x) cells_[std::size_t(y * cellsASide_ + x)].push_back(i);
  }
}

void RadialSurface::uniqueVerticesAndEdges() {
  const auto before = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  for (const auto& t : triangles_) vertices_.insert(vertices_.end(), t.begin(), t.end());
  std::sort(vertices_.begin(), vertices_.end(), before);
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
  const auto indexOf = [&](const glm::dvec3& p) {
    return std::size_t(std::lower_bound(vertices_.begin(), vertices_.end(), p, before) - vertices_.begin());
  };
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& t : triangles_)
    for (std::size_t e = 0; e < 3; ++e) edges.push_back(std::minmax(indexOf(t[e]), indexOf(t[(e + 1) % 3])));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) edges_.push_back({projected(vertices_[a]), projected(vertices_[b])});
}

glm::dvec2 RadialSurface::projected(const glm::dvec3& point) const {
  const glm::dvec3 onPlane = point * (glm::dot(normal_, origin_) / glm::dot(normal_, point)) - origin_;
  return {glm::dot(onPlane, u_), glm::dot(onPlane, v_)};
}

glm::dvec3 RadialSurface::direction(const glm::dvec2& onPlane) const {
  return glm::normalize(origin_ + onPlane.x * u_ + onPlane.y * v_);
}

bool RadialSurface::seenOnTheSamePlaneAs(const RadialSurface& other) const {
  return origin_ == other.origin_ && normal_ == other.normal_;
}

glm::ivec2 RadialSurface::cellOf(const glm::dvec2& onPlane) const {
  const glm::dvec2 f = (onPlane - low_) / glm::max(high_ - low_, glm::dvec2(1e-300)) * double(cellsASide_);
  return glm::clamp(glm::ivec2(glm::floor(f)), glm::ivec2(0), glm::ivec2(cellsASide_ - 1));
}

template <typename Visit>
void RadialSurface::forEachNear(const glm::dvec2& low, const glm::dvec2& high, Visit visit) const {
  const glm::ivec2 from = cellOf(low), to = cellOf(high);
  for (int y = from.y; y <= to.y; ++y)
    for (int x = from.x; x <= to.x; ++x)
      for (std::size_t t : cells_[std::size_t(y * cellsASide_ + x)]) visit(t);
}

std::optional<double> RadialSurface::radiusAlong(const glm::dvec3& direction) const {
  const glm::dvec2 p = projected(direction);
  std::size_t best = 0;
  double bestInside = -std::numeric_limits<double>::infinity();
  forEachNear(p, p, [&](std::size_t t) {
    const double inside = leastBarycentric(p, flat_[t]);
    if (inside > bestInside) best = t, bestInside = inside;
  });
  if (bestInside < -kBeyondEdge) return std::nullopt;
  const auto& t = triangles_[best];
  const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
  return glm::dot(n, t[0]) / glm::dot(n, direction);
}

std::vector<glm::dvec3> RadialSurface::vertexDirections() const {
  std::vector<glm::dvec3> directions;
  for (const glm::dvec3& p : vertices_) directions.push_back(glm::normalize(p));
  return directions;
}

std::vector<glm::dvec3> RadialSurface::crossingDirections(const RadialSurface& other) const {
  std::vector<glm::dvec3> directions;
  for (const auto& [a, b] : edges_)
    other.forEachNear(glm::min(a, b), glm::max(a, b), [&](std::size_t o) {
      for (int f = 0; f < 3; ++f) {  // a + s (b - a) = c + r (d - c), both within their segments
        const glm::dvec2 c = other.flat_[o][std::size_t(f)], d = other.flat_[o][std::size_t((f + 1) % 3)];
        const double denominator = cross(b - a, d - c);
        if (denominator == 0.0) continue;
        const double s = cross(c - a, d - c) / denominator, r = cross(c - a, b - a) / denominator;
        if (s > 0.0 && s < 1.0 && r > 0.0 && r < 1.0) directions.push_back(direction(a + s * (b - a)));
      }
    });
  return directions;
}

std::vector<std::array<glm::dvec3, 3>> trianglesOf(const DisplacedTriangle& triangle, const DisplacedPatch& patch) {
  std::vector<std::array<glm::dvec3, 3>> triangles;
  for (std::size_t t = 0; t + 2 < patch.indices.size(); t += 3)
    triangles.push_back({triangle.point(patch.vertices.at(patch.indices[t])),
                         triangle.point(patch.vertices.at(patch.indices[t + 1])),
                         triangle.point(patch.vertices.at(patch.indices[t + 2]))});
  return triangles;
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
