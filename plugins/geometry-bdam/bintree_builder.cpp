#include "bintree_builder.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <limits>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>

#include "diamond_simplification.hpp"
#include "diamonds.hpp"
#include "displaced_triangle.hpp"
#include "patch_codec.hpp"
#include "radial_deviation.hpp"

namespace strata::bdam {
namespace {

std::size_t indexOf(const BintreeNode& node) { return (std::size_t(node.root) << node.level) | node.path; }

// Calls work(item, worker) for every item below `count` on `threads` threads; the first exception is rethrown
// after the others stopped.
void inParallel(std::size_t count, unsigned threads, const std::function<void(std::size_t, unsigned)>& work) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failing;
  {
    std::vector<std::jthread> workers;
    for (unsigned w = 0; w < threads; ++w)
      workers.emplace_back([&, w] {
        try {
          for (std::size_t item; (item = next++) < count;) work(item, w);
        } catch (...) {
          const std::lock_guard lock(failing);
          if (!failure) failure = std::current_exception();
          next = count;
        }
      });
  }
  if (failure) std::rethrow_exception(failure);
}

std::vector<glm::dvec3> positionsOf(const DisplacedTriangle& triangle, const DisplacedPatch& patch) {
  std::vector<glm::dvec3> positions;
  for (const DisplacedVertex& v : patch.vertices) positions.push_back(triangle.point(v));
  return positions;
}

// About the middle of the points' and spheres' box, as far out as the farthest of them.
BoundingSphere enclosing(std::span<const glm::dvec3> points, std::span<const BoundingSphere> spheres) {
  glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : points) low = glm::min(low, p), high = glm::max(high, p);
  for (const BoundingSphere& s : spheres)
    low = glm::min(low, s.centre - s.radius), high = glm::max(high, s.centre + s.radius);
  BoundingSphere sphere{0.5 * (low + high), 0.0};
  for (const glm::dvec3& p : points) sphere.radius = std::max(sphere.radius, glm::length(p - sphere.centre));
  for (const BoundingSphere& s : spheres)
    sphere.radius = std::max(sphere.radius, glm::length(s.centre - sphere.centre) + s.radius);
  return sphere;
}

// The distance from the body's centre to the nearest point of a segment.
double nearestOnSegment(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 along = b - a;
  const double t =
      glm::dot(along, along) > 0.0 ? std::clamp(-glm::dot(a, along) / glm::dot(along, along), 0.0, 1.0) : 0.0;
  return glm::length(a + t * along);
}

// The distance from the body's centre to the nearest point of a triangle: the foot of the perpendicular to its plane
// where that lies inside it, else the nearest point of an edge (a wall along a frozen edge stands edge-on to the
// centre, its plane through it).
double nearestOnTriangle(const std::array<glm::dvec3, 3>& t) {
  const glm::dvec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
  if (glm::dot(normal, normal) > 0.0) {
    const glm::dvec3 foot = normal * (glm::dot(normal, t[0]) / glm::dot(normal, normal));
    bool inside = true;
    for (std::size_t e = 0; e < 3; ++e)
      inside = inside && glm::dot(glm::cross(t[(e + 1) % 3] - t[e], foot - t[e]), normal) >= 0.0;
    if (inside) return glm::length(foot);
  }
  return std::min({nearestOnSegment(t[0], t[1]), nearestOnSegment(t[1], t[2]), nearestOnSegment(t[2], t[0])});
}

// How near the centre and how far from it the triangles reach, m above `radius`: their farthest points are vertices.
std::pair<double, double> heightsOf(const std::vector<std::array<glm::dvec3, 3>>& triangles, double radius) {
  double lowest = std::numeric_limits<double>::max(), highest = -lowest;
  for (const auto& t : triangles) {
    lowest = std::min(lowest, nearestOnTriangle(t));
    for (const glm::dvec3& corner : t) highest = std::max(highest, glm::length(corner));
  }
  return {lowest - radius, highest - radius};
}

// A leaf's error against the terrain between its vertices: at each triangle's centroid.
double leafError(const DisplacedTriangle& triangle, const DisplacedPatch& patch, double radius,
                 const HeightAt& heights) {
  std::vector<std::array<glm::dvec3, 3>> triangles = trianglesOf(triangle, patch);
  std::vector<glm::dvec3> terrain;
  for (const auto& t : triangles) {
    const glm::dvec3 direction = glm::normalize(t[0] + t[1] + t[2]);
    terrain.push_back(direction * (radius + heights(direction)));
  }
  return radialDeviation(RadialSurface(triangle, std::move(triangles)), terrain);
}

// One level's patches as the level above reads them, by indexOf.
using DecodedLevel = std::vector<DisplacedPatch>;

class Builder {
 public:
  Builder(const HeightsForThread& heights, const BuildOptions& options) : options_(options), built_(options) {
    for (unsigned w = 0; w < options.threads; ++w) heights_.push_back(heights());
  }

  BuiltBintrees run(const std::function<void(const LevelReport&)>& progress) {
    DecodedLevel finer = level(options_.leafLevel, {}, progress);
    for (int l = options_.leafLevel - 1; l >= 0; --l) finer = level(l, finer, progress);
    return std::move(built_);
  }

 private:
  DecodedLevel level(int l, const DecodedLevel& finer, const std::function<void(const LevelReport&)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Diamond> diamonds = diamondsOf(l);
    DecodedLevel patches(std::size_t(kBintreeRoots) << l);
    inParallel(diamonds.size(), options_.threads, [&](std::size_t d, unsigned worker) {
      const Diamond& diamond = diamonds[d];
      const std::array<DisplacedPatch, 2> halves =
          finer.empty() ? leaves(diamond, heights_[worker]) : simplified(diamond, finer);
      for (int h = 0; h < 2; ++h) patches[indexOf(diamond.halves[std::size_t(h)])] = halves[std::size_t(h)];
      measure(diamond, halves, finer, heights_[worker]);
    });
    LevelReport report{l, diamonds.size(), 0, 0, 0.0};
    for (const Diamond& diamond : diamonds)
      for (const BintreeNode& half : diamond.halves) {
        report.storedBytes += built_.at(half).stored.size();
        report.triangles += patches[indexOf(half)].indices.size() / 3;
      }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress(report);
    return patches;
  }

  std::array<DisplacedPatch, 2> leaves(const Diamond& diamond, const HeightAt& heights) const {
    return {leafPatch(diamond.halves[0], options_.radius, heights, options_.divisions),
            leafPatch(diamond.halves[1], options_.radius, heights, options_.divisions)};
  }

  std::array<DisplacedPatch, 2> simplified(const Diamond& diamond, const DecodedLevel& finer) const {
    std::array<DisplacedPatch, 4> children;
    const std::array<BintreeNode, 4> nodes = diamond.children();
    for (std::size_t c = 0; c < 4; ++c) children[c] = finer[indexOf(nodes[c])];
    return simplifiedDiamond(diamond, children, options_.radius);
  }

  // The halves' error and sphere, shared; each one's error is the larger of its deviation from what it replaces
  // (the terrain for a leaf, its children's vertices above) plus what those had.
  void measure(const Diamond& diamond, const std::array<DisplacedPatch, 2>& halves, const DecodedLevel& finer,
               const HeightAt& heights) {
    double error = 0.0;
    std::vector<glm::dvec3> points;
    std::vector<BoundingSphere> spheres;
    for (std::size_t h = 0; h < 2; ++h) {
      const DisplacedTriangle triangle = displacedTriangle(diamond.halves[h], options_.radius);
      const std::vector<glm::dvec3> own = positionsOf(triangle, halves[h]);
      points.insert(points.end(), own.begin(), own.end());
      error = std::max(error, finer.empty() ? leafError(triangle, halves[h], options_.radius, heights)
                                            : deviationFromChildren(diamond, h, triangle, halves[h], finer, spheres));
    }
    const BoundingSphere sphere = enclosing(points, spheres);
    for (std::size_t h = 0; h < 2; ++h) {
      BuiltNode& node = built_.at(diamond.halves[h]);
      node.stored = encodePatch(halves[h]);
      node.vertices = std::uint32_t(halves[h].vertices.size());
      node.indices = std::uint32_t(halves[h].indices.size());
      node.error = error;
      node.sphere = sphere;
      std::tie(node.lowest, node.highest) =
          heightsOf(trianglesOf(displacedTriangle(diamond.halves[h], options_.radius), halves[h]), options_.radius);
    }
  }

  double deviationFromChildren(const Diamond& diamond, std::size_t h, const DisplacedTriangle& triangle,
                               const DisplacedPatch& half, const DecodedLevel& finer,
                               std::vector<BoundingSphere>& spheres) const {
    std::vector<std::array<glm::dvec3, 3>> replaced;
    double childrenError = 0.0;
    for (std::size_t c = 2 * h; c < 2 * h + 2; ++c) {
      const BintreeNode child = diamond.children()[c];
      const auto own = trianglesOf(displacedTriangle(child, options_.radius), finer[indexOf(child)]);
      replaced.insert(replaced.end(), own.begin(), own.end());
      childrenError = std::max(childrenError, built_.at(child).error);
      spheres.push_back(built_.at(child).sphere);
    }
    return radialDeviation(RadialSurface(triangle, trianglesOf(triangle, half)),
                           RadialSurface(triangle, std::move(replaced))) +
           childrenError;
  }

  BuildOptions options_;
  BuiltBintrees built_;
  std::vector<HeightAt> heights_;
};

}  // namespace

BuiltBintrees::BuiltBintrees(const BuildOptions& options) : options_(options) {
  for (int l = 0; l <= options.leafLevel; ++l) levels_.emplace_back(std::size_t(kBintreeRoots) << l);
}

const BuiltNode& BuiltBintrees::at(const BintreeNode& node) const {
  return levels_.at(std::size_t(node.level)).at(indexOf(node));
}

BuiltNode& BuiltBintrees::at(const BintreeNode& node) { return levels_.at(std::size_t(node.level)).at(indexOf(node)); }

BuiltBintrees buildBintrees(const HeightsForThread& heights, const BuildOptions& options,
                            const std::function<void(const LevelReport&)>& progress) {
  if (!(options.radius > 0.0)) throw std::invalid_argument("a body's radius must be positive");
  if (options.leafLevel < 0 || options.leafLevel > 30)
    throw std::invalid_argument("a leaf level of " + std::to_string(options.leafLevel) + ": 0 to 30");
  BuildOptions resolved = options;
  if (resolved.threads == 0) resolved.threads = std::max(1u, std::thread::hardware_concurrency());
  return Builder(heights, resolved).run(progress);
}

}  // namespace strata::bdam
