#include "node_batch.hpp"

#include <cmath>
#include <numbers>

#include "stitched_grid.hpp"

namespace strata::healpix {
namespace {

// The frame's reference point (View::reference) and the rotation to its east-north-up frame.
struct Reference {
  glm::dvec3 unit;
  glm::dmat3 planetToLocal;
};

glm::vec4 facePointOf(const FacePoint& point) { return {float(point.face), float(point.x), float(point.y), 0.0f}; }

GpuNode gpuNode(const NodeKey& key, const View& view, double radius, int cells, const Reference& reference) {
  const double size = std::ldexp(1.0, -key.level);
  const FacePoint centre{key.face, (double(key.ix) + 0.5) * size, (double(key.iy) + 0.5) * size};
  const glm::dvec3 unit = unitVector(centre);
  const double longitude = std::remainder(lonlat(centre).x - view.reference.x, 2.0 * std::numbers::pi);
  return {frameAt(centre), glm::vec4(glm::vec3(radius * unit - view.eye), float(size / cells)),
          glm::vec4(glm::vec3(reference.planetToLocal * (unit - reference.unit)), float(longitude)),
          glm::vec4(glm::vec3(unit), 0.0f), facePointOf(key.at(0.0, 0.0))};
}

// The outline of a node, 4 cells vertices from corner 0 round to corner 0, each edge from its first corner.
void appendBoundary(const NodeKey& key, const View& view, double radius, int cells, const Reference& reference,
                    std::vector<BoundaryVertex>& boundary) {
  const glm::ivec2 start[4] = {{0, 0}, {cells, 0}, {cells, cells}, {0, cells}};
  const glm::ivec2 step[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  for (int edge = 0; edge < 4; ++edge)
    for (int k = 0; k < cells; ++k) {
      const glm::dvec2 lattice(start[edge] + k * step[edge]);
      const FacePoint point = key.at(lattice.x / cells, lattice.y / cells);
      const glm::dvec3 unit = unitVector(point);
      boundary.push_back({glm::vec4(glm::vec3(radius * unit - view.eye), 0.0f),
                          glm::vec4(glm::vec3(reference.planetToLocal * (unit - reference.unit)), 0.0f),
                          glm::vec4(glm::vec3(unit), 0.0f), facePointOf(point)});
    }
}

}  // namespace

NodeBatch batchNodes(std::span<const SelectedNode> selected, const View& view, double radius, int cells) {
  const Reference reference{unitNormal(view.reference.x, view.reference.y), planetToLocal(view.reference)};
  const std::uint32_t indicesPerNode = 6u * std::uint32_t(cells) * std::uint32_t(cells);
  NodeBatch batch;
  batch.nodes.reserve(selected.size());
  batch.draws.reserve(selected.size());
  batch.boundary.reserve(selected.size() * 4 * std::size_t(cells));
  for (const SelectedNode& node : selected) {
    batch.draws.push_back(
        {indicesPerNode, 1, node.coarserEdges * indicesPerNode, 0, std::uint32_t(batch.nodes.size())});
    batch.nodes.push_back(gpuNode(node.key, view, radius, cells, reference));
    appendBoundary(node.key, view, radius, cells, reference, batch.boundary);
  }
  return batch;
}

}  // namespace strata::healpix
