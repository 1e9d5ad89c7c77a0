// Drawn neighbours differ by at most one level across every edge, base-face edges included, and
// coarserEdges marks exactly the edges with a coarser neighbour. Checked on the sphere, apart from the
// selection's own neighbour search: every selected node's edges are sampled at 2^-6 steps and hashed by
// position; the middle of a node's edge then meets every node across it whose level is at most 5 coarser
// (the middle lies at an odd multiple of 2^-(d + 1) along a node d levels coarser) or any finer, as one of
// those samples, to rounding (unitVector agrees across faces to 1e-15).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "selection_views.hpp"

namespace strata::healpix {
namespace {

constexpr int kSteps = 64;
constexpr double kCell = 1e-10, kMatch = 1e-13;  // on the unit sphere

struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell&) const = default;
};
struct CellHash {
  std::size_t operator()(const Cell& c) const { return std::size_t(c.x * 73856093 ^ c.y * 19349663 ^ c.z * 83492791); }
};

class EdgeSamples {
 public:
  explicit EdgeSamples(const std::vector<SelectedNode>& nodes) {
    const std::array<std::array<double, 2>, 4> corners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      for (std::size_t e = 0; e < 4; ++e) {
        const auto &a = corners[e], &b = corners[(e + 1) % 4];
        for (int k = 0; k <= kSteps; ++k) {
          const double t = double(k) / kSteps;
          const glm::dvec3 u = unitVector(nodes[n].key.at(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])));
          cells_[cellOf(u)].push_back({u, n});
        }
      }
    }
  }

  // The nodes with a sample within kMatch of u.
  std::vector<std::size_t> nodesAt(const glm::dvec3& u) const {
    std::vector<std::size_t> found;
    const Cell c = cellOf(u);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto cell = cells_.find({c.x + dx, c.y + dy, c.z + dz});
          if (cell == cells_.end()) continue;
          for (const auto& [v, n] : cell->second) {
            if (glm::length(v - u) < kMatch && std::find(found.begin(), found.end(), n) == found.end())
              found.push_back(n);
          }
        }
      }
    }
    return found;
  }

 private:
  static Cell cellOf(const glm::dvec3& u) {
    return {std::llround(u.x / kCell), std::llround(u.y / kCell), std::llround(u.z / kCell)};
  }
  std::unordered_map<Cell, std::vector<std::pair<glm::dvec3, std::size_t>>, CellHash> cells_;
};

TEST(NodeBalance, NeighboursDifferByAtMostOneLevelAndCoarserEdgesAreExact) {
  for (const TestView& test : testViews()) {
    const std::vector<SelectedNode> nodes = selectNodes(test.view(), kEarthRadius, test.heights, {});
    const EdgeSamples samples(nodes);
    int pairs = 0, acrossFaces = 0, coarser = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const NodeKey& key = nodes[n].key;
      for (int e = 0; e < 4; ++e) {
        const FacePoint middle = key.at(e == 1 ? 1.0 : e == 3 ? 0.0 : 0.5, e == 2 ? 1.0 : e == 0 ? 0.0 : 0.5);
        bool coarserAcross = false;
        for (const std::size_t m : samples.nodesAt(unitVector(middle))) {
          if (m == n) continue;
          const NodeKey& other = nodes[m].key;
          ++pairs;
          acrossFaces += other.face != key.face;
          ASSERT_LE(std::abs(other.level - key.level), 1)
              << test.name << ": face " << key.face << " level " << key.level << " edge " << e << " meets face "
              << other.face << " level " << other.level;
          coarserAcross = coarserAcross || other.level == key.level - 1;
        }
        coarser += coarserAcross;
        ASSERT_EQ(bool(nodes[n].coarserEdges & (1u << e)), coarserAcross)
            << test.name << ": face " << key.face << " level " << key.level << " edge " << e;
      }
    }
    std::printf("%-36s %6d edge contacts, %4d across faces, %5d coarser edges\n", test.name.c_str(), pairs, acrossFaces,
                coarser);
    EXPECT_GT(pairs, 0) << test.name;
  }
}

}  // namespace
}  // namespace strata::healpix
