#include "patch_batch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strata::icosahedral {
namespace {

// The longitude of the patch's centre, unwrapped to within pi of the reference: the corners are unwrapped
// around it, so a patch across the antimeridian keeps its corners together.
double centreLongitude(const SphericalTriangle& corners, double referenceLon) {
  const glm::dvec3 centre = corners[0] + corners[1] + corners[2];
  const double lon = std::atan2(centre.y, centre.x);
  return referenceLon + std::remainder(lon - referenceLon, 2.0 * std::numbers::pi);
}

}  // namespace

PatchBatch batchPatches(const std::vector<Patch>& patches, const View& view, double radius, double splitDistanceUnit,
                        const SubdivisionTable& table, const EdgeWindings& windings) {
  PatchBatch batch{.reference = {view.reference.x, view.reference.y},
                   .splitDistanceUnit = splitDistanceUnit,
                   .footprintPerMetre = kFaceEdgeAngle / (std::numbers::sqrt2 * table.segments() * splitDistanceUnit)};
  batch.seeds.reserve(3 * patches.size());
  batch.draws.reserve(patches.size());
  const glm::dvec2 reference(batch.reference.lon, batch.reference.lat);
  for (const Patch& patch : patches) {
    const PatchSeed seed = patchSeed(patch.corners, radius, view.eye, centreLongitude(patch.corners, reference.x));
    for (std::size_t c = 0; c < 3; ++c)
      batch.seeds.push_back({glm::vec4(glm::vec3(seed.positions[c]), float(patch.level)),
                             glm::vec4(glm::vec3(seed.normals[c]), 0.0f),
                             glm::vec4(glm::vec2(seed.lonlat[c] - reference), 0.0f, 0.0f)});
    batch.details.insert(batch.details.end(), patch.details.begin(), patch.details.end());
    const IndexRange winding = windings.range(patch.coarseEdges);
    batch.draws.push_back({winding.count, 1, winding.first, std::int32_t(batch.draws.size()) * table.vertexCount(), 0});
  }
  return batch;
}

}  // namespace strata::icosahedral
