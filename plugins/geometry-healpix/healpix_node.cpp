#include "healpix_node.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace strata::healpix {
namespace {

// The unit corner offsets (u, v) of corners 0 to 3 and the outward direction of edges 0 to 3.
constexpr std::array<std::array<double, 2>, 4> kCorners{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
constexpr std::array<std::array<double, 2>, 4> kOutward{{{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}}};

bool onFace(double x, double y) { return x > 0.0 && x < 1.0 && y > 0.0 && y < 1.0; }

FacePoint facePointOf(const glm::dvec3& unit) {
  return facePoint({std::atan2(unit.y, unit.x), std::atan2(unit.z, std::hypot(unit.x, unit.y))});
}

}  // namespace

double NodeKey::size() const { return std::ldexp(1.0, -level); }

std::array<NodeKey, 4> NodeKey::children() const {
  const int l = level + 1;
  return {NodeKey{face, l, 2 * ix, 2 * iy}, NodeKey{face, l, 2 * ix + 1, 2 * iy}, NodeKey{face, l, 2 * ix, 2 * iy + 1},
          NodeKey{face, l, 2 * ix + 1, 2 * iy + 1}};
}

NodeKey NodeKey::parent() const { return {face, level - 1, ix / 2, iy / 2}; }

FacePoint NodeKey::at(double u, double v) const {
  return {face, std::ldexp(double(ix) + u, -level), std::ldexp(double(iy) + v, -level)};
}

FacePoint NodeKey::corner(int corner) const {
  const auto& uv = kCorners[std::size_t(corner)];
  return at(uv[0], uv[1]);
}

bool NodeKey::holds(const FacePoint& point) const {
  if (point.face != face) return false;
  // Scaling by 2^level is exact, so the comparisons with the integer bounds are too.
  const double x = std::ldexp(point.x, level), y = std::ldexp(point.y, level);
  const double last = std::ldexp(1.0, level) - 1.0;
  const auto within = [last](double t, std::int64_t i) {
    return t >= double(i) && (t < double(i + 1) || (double(i) == last && t <= double(i + 1)));
  };
  return within(x, ix) && within(y, iy);
}

std::size_t NodeKeyHash::operator()(const NodeKey& key) const {
  const auto mix = [](std::uint64_t h, std::uint64_t v) { return (h ^ v) * 0x100000001b3ULL + (h >> 29); };
  std::uint64_t h = 0xcbf29ce484222325ULL;
  h = mix(h, std::uint64_t(key.face) << 8 | std::uint64_t(key.level));
  h = mix(h, std::uint64_t(key.ix));
  h = mix(h, std::uint64_t(key.iy));
  return std::size_t(h ^ (h >> 32));
}

NodeKey nodeAt(const FacePoint& point, int level) {
  const double n = std::ldexp(1.0, level);
  const auto index = [n](double t) { return std::int64_t(std::clamp(std::floor(t * n), 0.0, n - 1.0)); };
  return {point.face, level, index(point.x), index(point.y)};
}

FacePoint acrossEdge(const NodeKey& key, int edge) {
  const auto& out = kOutward[std::size_t(edge)];
  const auto& a = kCorners[std::size_t(edge)];
  const auto& b = kCorners[std::size_t((edge + 1) % 4)];
  const FacePoint middle = key.at(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
  const double step = key.size() / 64.0;
  const double x = middle.x + out[0] * step, y = middle.y + out[1] * step;
  if (onFace(x, y)) return {key.face, x, y};
  const glm::dvec3 inside = unitVector({key.face, middle.x - out[0] * step, middle.y - out[1] * step});
  return facePointOf(glm::normalize(2.0 * unitVector(middle) - inside));
}

std::array<glm::dvec3, 8> boundarySamples(const NodeKey& key) {
  std::array<glm::dvec3, 8> samples;
  for (std::size_t c = 0; c < 4; ++c) {
    const auto& a = kCorners[c];
    const auto& b = kCorners[(c + 1) % 4];
    samples[2 * c] = unitVector(key.at(a[0], a[1]));
    samples[2 * c + 1] = unitVector(key.at(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])));
  }
  return samples;
}

NodeCone coneAround(const glm::dvec3& axis, const std::array<glm::dvec3, 8>& boundary) {
  double widest = 0.0;
  for (const glm::dvec3& u : boundary) widest = std::max(widest, angleBetween(axis, u));
  return {axis, kConeMargin * widest};
}

NodeCone coneOf(const NodeKey& key) { return coneAround(unitVector(key.centre()), boundarySamples(key)); }

}  // namespace strata::healpix
