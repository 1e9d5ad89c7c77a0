#include "patch_batch.hpp"

#include <cmath>
#include <numbers>

#include "displaced_triangle.hpp"

namespace strata::bdam {
namespace {

GpuPatch gpuPatchOf(const BintreeNode& node, const View& view, double radius) {
  const DisplacedTriangle t = displacedTriangle(node, radius);
  GpuPatch patch{};
  for (std::size_t i = 0; i < 3; ++i) {
    patch.corners[i] = glm::vec4(glm::vec3(t.corners[i] - view.eye), 0.0f);
    patch.normals[i] = glm::vec4(glm::vec3(t.normals[i]), 0.0f);
  }
  patch.edges[0] = glm::vec4(glm::vec3(t.corners[1] - t.corners[0]), 0.0f);
  patch.edges[1] = glm::vec4(glm::vec3(t.corners[2] - t.corners[0]), 0.0f);
  const glm::dvec3 middle = t.corners[0] + t.corners[1] + t.corners[2];
  const double longitude = std::atan2(middle.y, middle.x) - view.reference.x;
  patch.centre.x = float(std::remainder(longitude, 2.0 * std::numbers::pi));
  for (unsigned e = 0; e < 3; ++e)
    if (t.edgeRunsBackwards(int(e))) patch.edgeOrder.x |= 1u << e;
  return patch;
}

}  // namespace

PatchBatch batchPatches(std::span<const PlacedNode> placed, const View& view, double radius, std::uint32_t mostVertices,
                        std::uint32_t mostIndices) {
  PatchBatch batch;
  for (const PlacedNode& p : placed) {
    batch.draws.push_back({p.indices, 1, std::uint32_t(p.slot * mostIndices), std::int32_t(p.slot * mostVertices),
                           std::uint32_t(batch.patches.size())});
    batch.patches.push_back(gpuPatchOf(p.node, view, radius));
  }
  return batch;
}

}  // namespace strata::bdam
