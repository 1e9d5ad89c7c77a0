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

// Diamonds built between two appends to their level's file: enough that the workers seldom wait for the last of them
// (seconds of work), few enough that their patches take a few megabytes.
constexpr std::size_t kDiamondsAtATime = 4096;

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
std::pair<double, double> heightsOf(const PlanetMesh& mesh, double radius) {
  double lowest = std::numeric_limits<double>::max(), highest = -lowest;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    lowest = std::min(lowest, nearestOnTriangle({mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                                                 mesh.positions[mesh.indices[t + 2]]}));
  for (const glm::dvec3& p : mesh.positions) highest = std::max(highest, glm::length(p));
  return {lowest - radius, highest - radius};
}

// A leaf's error against the terrain between its vertices: at each triangle's centroid.
double leafError(const DisplacedTriangle& triangle, const DisplacedPatch& patch, double radius,
                 const HeightAt& heights) {
  const PlanetMesh mesh = meshOf(triangle, patch);
  std::vector<glm::dvec3> terrain;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 direction = glm::normalize(mesh.positions[mesh.indices[t]] + mesh.positions[mesh.indices[t + 1]] +
                                                mesh.positions[mesh.indices[t + 2]]);
    terrain.push_back(direction * (radius + heights(direction)));
  }
  return radialDeviation(RadialSurface(triangle, mesh), terrain);
}

// The children of a diamond, decoded from what the level below stored (none for leaves).
using Children = std::array<DisplacedPatch, 4>;
// A diamond's halves as encodePatch stores them.
using StoredHalves = std::array<std::vector<std::byte>, 2>;

class Builder {
 public:
  Builder(const HeightsForThread& heights, const BuildOptions& options) : options_(options), built_(options) {
    for (unsigned w = 0; w < options.threads; ++w) heights_.push_back(heights());
  }

  BuiltBintrees run(const std::function<void(const LevelReport&)>& progress) {
    for (int l = options_.leafLevel; l >= 0; --l) progress(level(l));
    return std::move(built_);
  }

 private:
  LevelReport level(int l) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Diamond> diamonds = diamondsOf(l);
    LevelReport report{l, diamonds.size(), 0, 0, 0.0};
    LevelPatches& patches = built_.patchesOf(l);
    for (std::size_t from = 0; from < diamonds.size(); from += kDiamondsAtATime) {
      const std::span<const Diamond> some =
          std::span(diamonds).subspan(from, std::min(kDiamondsAtATime, diamonds.size() - from));
      std::vector<StoredHalves> stored(some.size());
      inParallel(some.size(), options_.threads,
                 [&](std::size_t d, unsigned worker) { stored[d] = halvesOf(some[d], heights_[worker]); });
      for (std::size_t d = 0; d < some.size(); ++d)
        for (std::size_t h = 0; h < 2; ++h) {
          BuiltNode& node = built_.at(some[d].halves[h]);
          node.offset = patches.append(stored[d][h]);
          node.bytes = std::uint32_t(stored[d][h].size());
          report.storedBytes += node.bytes;
          report.triangles += node.indices / 3;
        }
    }
    patches.finish();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

  StoredHalves halvesOf(const Diamond& diamond, const HeightAt& heights) {
    if (diamond.halves[0].level == options_.leafLevel) return measure(diamond, leaves(diamond, heights), {}, heights);
    Children children;
    for (std::size_t c = 0; c < 4; ++c) children[c] = decodePatch(built_.stored(diamond.children()[c]));
    return measure(diamond, simplifiedDiamond(diamond, children, options_.radius), children, heights);
  }

  std::array<DisplacedPatch, 2> leaves(const Diamond& diamond, const HeightAt& heights) const {
    return {leafPatch(diamond.halves[0], options_.radius, heights, options_.divisions),
            leafPatch(diamond.halves[1], options_.radius, heights, options_.divisions)};
  }

  // The halves' error and sphere, shared; each one's error is the larger of its deviation from what it replaces
  // (the terrain for a leaf, its children's surface above) plus what those had.
  StoredHalves measure(const Diamond& diamond, const std::array<DisplacedPatch, 2>& halves, const Children& children,
                       const HeightAt& heights) {
    const bool leaf = diamond.halves[0].level == options_.leafLevel;
    double error = 0.0;
    std::vector<glm::dvec3> points;
    std::vector<BoundingSphere> spheres;
    for (std::size_t h = 0; h < 2; ++h) {
      const DisplacedTriangle triangle = displacedTriangle(diamond.halves[h], options_.radius);
      const std::vector<glm::dvec3> own = positionsOf(triangle, halves[h]);
      points.insert(points.end(), own.begin(), own.end());
      error = std::max(error, leaf ? leafError(triangle, halves[h], options_.radius, heights)
                                   : deviationFromChildren(diamond, h, triangle, halves[h], children, spheres));
    }
    const BoundingSphere sphere = enclosing(points, spheres);
    StoredHalves stored;
    for (std::size_t h = 0; h < 2; ++h) {
      BuiltNode& node = built_.at(diamond.halves[h]);
      stored[h] = encodePatch(halves[h]);
      node.vertices = std::uint32_t(halves[h].vertices.size());
      node.indices = std::uint32_t(halves[h].indices.size());
      node.error = error;
      node.sphere = sphere;
      std::tie(node.lowest, node.highest) =
          heightsOf(meshOf(displacedTriangle(diamond.halves[h], options_.radius), halves[h]), options_.radius);
    }
    return stored;
  }

  double deviationFromChildren(const Diamond& diamond, std::size_t h, const DisplacedTriangle& triangle,
                               const DisplacedPatch& half, const Children& children,
                               std::vector<BoundingSphere>& spheres) const {
    PlanetMesh replaced;
    double childrenError = 0.0;
    for (std::size_t c = 2 * h; c < 2 * h + 2; ++c) {
      const BintreeNode child = diamond.children()[c];
      replaced.append(meshOf(displacedTriangle(child, options_.radius), children[c]));
      childrenError = std::max(childrenError, built_.at(child).error);
      spheres.push_back(built_.at(child).sphere);
    }
    return radialDeviation(RadialSurface(triangle, meshOf(triangle, half)), RadialSurface(triangle, replaced)) +
           childrenError;
  }

  BuildOptions options_;
  BuiltBintrees built_;
  std::vector<HeightAt> heights_;
};

}  // namespace

BuiltBintrees::BuiltBintrees(const BuildOptions& options) : options_(options) {
  for (int l = 0; l <= options.leafLevel; ++l) {
    levels_.emplace_back(std::size_t(kBintreeRoots) << l);
    patches_.push_back(std::make_unique<LevelPatches>(options.scratch / ("level-" + std::to_string(l) + ".patches")));
  }
}

const BuiltNode& BuiltBintrees::at(const BintreeNode& node) const {
  return levels_.at(std::size_t(node.level)).at(indexOf(node));
}

BuiltNode& BuiltBintrees::at(const BintreeNode& node) { return levels_.at(std::size_t(node.level)).at(indexOf(node)); }

std::span<const std::byte> BuiltBintrees::stored(const BintreeNode& node) const {
  const BuiltNode& built = at(node);
  return patches_.at(std::size_t(node.level))->at(built.offset, built.bytes);
}

BuiltBintrees buildBintrees(const HeightsForThread& heights, const BuildOptions& options,
                            const std::function<void(const LevelReport&)>& progress) {
  if (!(options.radius > 0.0)) throw std::invalid_argument("a body's radius must be positive");
  if (options.leafLevel < 0 || options.leafLevel > 30)
    throw std::invalid_argument("a leaf level of " + std::to_string(options.leafLevel) + ": 0 to 30");
  if (!std::filesystem::is_directory(options.scratch))
    throw std::invalid_argument("a build needs a scratch folder for its levels' patches: " + options.scratch.string());
  BuildOptions resolved = options;
  if (resolved.threads == 0) resolved.threads = std::max(1u, std::thread::hardware_concurrency());
  return Builder(heights, resolved).run(progress);
}

}  // namespace strata::bdam
