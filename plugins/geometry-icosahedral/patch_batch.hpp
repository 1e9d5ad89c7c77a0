#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl/indirect_draw.hpp>

#include "edge_windings.hpp"
#include "geodesic_subdivision.hpp"
#include "patch_tree.hpp"

namespace strata::icosahedral {

// One corner of a seed as the compute pass reads it (std430: three vec4).
struct SeedCorner {
  glm::vec4 position;  // xyz: m on the sphere, relative to the eye, planet-fixed axes; w: the patch's level
  glm::vec4 normal;    // xyz: planet-fixed unit normal
  glm::vec4 lonlat;    // xy: rad from the frame's reference, longitude unwrapped
};

// What one frame uploads for the visible patches ([Kooima 2008, §3.2.4], its "seed textures"): three
// corners per patch, computed in double and made eye-relative before they become float
// [Kooima 2008, §3.2.5], and the draw of each patch with the edge winding its coarser neighbours call for
// [Kooima 2008, §3.4.1].
struct PatchBatch {
  LonLatReference reference;  // View::reference, the point below the eye: longitude and latitude are measured from it
  double splitDistanceUnit = 0.0;  // m: PatchTree::splitDistanceUnit(), for the morphs
  // The angle between neighbouring vertices, rad, per metre of their face-on distance, where a patch's
  // vertices lie between its split distance and twice that (the geometric middle) and the detail scale is 1: the
  // compute pass divides it by each vertex's. As a function of the vertex alone it gives a vertex shared by two
  // patches the same height footprint in both, so that the displaced surface stays closed where their levels
  // differ.
  double footprintPerMetre = 0.0;
  // Whether vertices measure their face-on distances at their displaced points, as the tree measures to each
  // patch's own shell (PatchTree::measuresOnTerrain), or on the sphere.
  bool onTerrain = false;
  std::vector<SeedCorner> seeds;
  std::vector<float> details;  // DetailField::kPatchValues a patch: Patch::details
  std::vector<DrawElementsIndirectCommand> draws;
};

PatchBatch batchPatches(const std::vector<Patch>& patches, const View& view, double radius, double splitDistanceUnit,
                        const SubdivisionTable& table, const EdgeWindings& windings);

}  // namespace strata::icosahedral
