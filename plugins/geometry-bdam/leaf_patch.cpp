#include "leaf_patch.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "displaced_triangle.hpp"
#include "patch_order.hpp"

namespace strata::bdam {
namespace {

// Steps at most: each step's error is the last's times the terrain's slope times the normal's lean from the radial,
// under a thousandth on any body's relief; and the change, m, at which they stop: under the stored centimetre.
constexpr int kTerrainSteps = 8;
constexpr double kTerrainTolerance = 1e-3;

// The displacement along N(b) to the terrain: the height at the flat point's direction, then at the direction of the
// point that height gives, until it moves less than a millimetre.
double displacementToTerrain(const DisplacedTriangle& triangle, double b1, double b2, double radius,
                             const HeightAt& heights) {
  const glm::dvec3 flat = triangle.flatPoint(b1, b2), normal = triangle.normal(b1, b2);
  double h = triangle.displacementTo(b1, b2, radius + heights(glm::normalize(flat)));
  for (int step = 1; step < kTerrainSteps; ++step) {
    const double next = triangle.displacementTo(b1, b2, radius + heights(glm::normalize(flat + h * normal)));
    if (std::abs(next - h) < kTerrainTolerance) return next;
    h = next;
  }
  return h;
}

}  // namespace

DisplacedPatch leafPatch(const BintreeNode& node, double radius, const HeightAt& heights, int divisions) {
  if (divisions < 1 || divisions > kBarycentricSteps)
    throw std::invalid_argument("a leaf patch of " + std::to_string(divisions) + " divisions a side");
  const DisplacedTriangle triangle = displacedTriangle(node, radius);
  DisplacedPatch patch;
  std::vector<std::vector<std::uint32_t>> rows;
  for (int j = 0; j <= divisions; ++j) {
    rows.emplace_back();
    for (int i = 0; i + j <= divisions; ++i) {
      const DisplacedVertex quantised = displacedVertex(double(i) / divisions, double(j) / divisions, 0.0);
      const double b1 = double(quantised.b1) / kBarycentricSteps, b2 = double(quantised.b2) / kBarycentricSteps;
      rows.back().push_back(std::uint32_t(patch.vertices.size()));
      patch.vertices.push_back(displacedVertex(b1, b2, displacementToTerrain(triangle, b1, b2, radius, heights)));
    }
  }
  for (int j = 0; j < divisions; ++j)
    for (int i = 0; i + j < divisions; ++i) {
      const auto at = [&rows](int column, int row) { return rows[std::size_t(row)][std::size_t(column)]; };
      patch.indices.insert(patch.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < divisions)
        patch.indices.insert(patch.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return orderedForDrawing(patch);
}

}  // namespace strata::bdam
