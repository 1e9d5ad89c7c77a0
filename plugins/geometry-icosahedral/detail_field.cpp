#include "detail_field.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "subdivision_table.hpp"

namespace strata::icosahedral {
namespace {

std::uint64_t bitsOf(const glm::dvec3& direction) {
  const std::uint64_t x = std::bit_cast<std::uint64_t>(direction.x), y = std::bit_cast<std::uint64_t>(direction.y),
                      z = std::bit_cast<std::uint64_t>(direction.z);
  return x ^ (y * 0x9e3779b97f4a7c15ULL) ^ (z * 0xc2b2ae3d27d4eb4fULL);
}

}  // namespace

// The lattice as the patch tree splits faces (patch_topology.cpp): each edge's midpoint made once, from the same
// two bits-identical ends, so that the tree's vertices of levels up to kLevel hold the lattice's bits.
DetailField::DetailField(double initial) {
  std::map<std::pair<int, int>, int> midpoints;
  const auto add = [&](const glm::dvec3& direction) {
    const auto found = std::ranges::find(directions_, direction);
    if (found != directions_.end()) return int(found - directions_.begin());
    directions_.push_back(direction);
    return int(directions_.size() - 1);
  };
  const auto midpoint = [&](int a, int b) {
    const auto [it, made] = midpoints.try_emplace(std::minmax(a, b), 0);
    if (made) it->second = add(greatCircleMidpoint(directions_[std::size_t(a)], directions_[std::size_t(b)]));
    return it->second;
  };
  std::vector<std::array<int, 3>> triangles;
  for (const SphericalTriangle& face : icosahedronFaces())
    triangles.push_back({add(face[0]), add(face[1]), add(face[2])});
  for (int level = 0; level < kLevel; ++level) {
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : triangles) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
    }
    triangles = std::move(finer);
  }
  std::vector<std::set<int>> neighbours(directions_.size());
  for (const auto& triangle : triangles)
    for (std::size_t e = 0; e < 3; ++e) {
      neighbours[std::size_t(triangle[e])].insert(triangle[(e + 1) % 3]);
      neighbours[std::size_t(triangle[(e + 1) % 3])].insert(triangle[e]);
    }
  for (const std::set<int>& around : neighbours) neighbours_.emplace_back(around.begin(), around.end());
  for (std::size_t v = 0; v < directions_.size(); ++v) byDirection_.emplace(bitsOf(directions_[v]), int(v));
  values_.assign(directions_.size(), initial);
}

int DetailField::vertexAt(const glm::dvec3& direction) const {
  if (const auto found = byDirection_.find(bitsOf(direction));
      found != byDirection_.end() && directions_[std::size_t(found->second)] == direction)
    return found->second;
  int nearest = 0;
  for (std::size_t v = 1; v < directions_.size(); ++v)
    if (glm::dot(directions_[v], direction) > glm::dot(directions_[std::size_t(nearest)], direction)) nearest = int(v);
  return nearest;
}

const std::vector<int>& DetailField::gridOf(const SphericalTriangle& corners, int level) const {
  const auto [kept, found] =
      grids_.try_emplace({vertexAt(corners[0]), vertexAt(corners[1]), vertexAt(corners[2]), level}, std::vector<int>());
  if (!found) return kept->second;
  const SubdivisionTable table(std::max(kLevel - level, 0));
  std::vector<glm::dvec3> directions(corners.begin(), corners.end());
  std::vector<int> grid;
  for (std::uint32_t v = 0; v < std::uint32_t(table.vertexCount()); ++v) {
    if (v >= 3) {
      const auto [a, b] = table.parents(v);
      directions.push_back(greatCircleMidpoint(directions[a], directions[b]));
    }
    grid.push_back(vertexAt(directions[v]));
  }
  kept->second = std::move(grid);
  return kept->second;
}

// A shortest-path relaxation in the logarithm: each pass raises a vertex to its largest neighbour over the
// ratio; the raised values only grow, so passes end once none changes (at most the lattice's diameter).
std::vector<double> DetailField::smoothed(std::vector<double> wanted) const {
  bool raised = true;
  while (raised) {
    raised = false;
    for (std::size_t v = 0; v < wanted.size(); ++v)
      for (const int n : neighbours_[v])
        if (wanted[std::size_t(n)] / kNeighbourRatio > wanted[v]) {
          wanted[v] = wanted[std::size_t(n)] / kNeighbourRatio;
          raised = true;
        }
  }
  return wanted;
}

}  // namespace strata::icosahedral
