#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl/indirect_draw.hpp>

#include "cube_bintree.hpp"

namespace strata::bdam {

// A drawn patch as bdam_surface.vert reads it (std430): its displaced triangle's corners made relative to the eye
// in double on the CPU and only then rounded, as the paper sends them [Cignoni et al. 2003, §4.2: "9 subtractions and
// 9 float conversions per patch"], so that the GPU adds only small values (docs/architecture.md, "Precision").
struct GpuPatch {
  glm::vec4 corners[3];  // xyz: P_i minus the eye, m, planet-fixed
  glm::vec4 normals[3];  // xyz: N_i, unit, planet-fixed
  glm::vec4 edges[2];    // xyz: P1 - P0 and P2 - P0, differences taken in double
  glm::vec4 centre;      // x: the patch's longitude from View::reference, rad, in [-pi, pi]
  // x: bit e set where the edge opposite corner e runs from its higher-numbered corner: its lexicographically lesser
  // end (displaced_triangle.hpp), from which both patches sharing it form its points
  glm::uvec4 edgeOrder;
};

// A node to draw and the slot of the GPU's buffers its patch is in.
struct PlacedNode {
  BintreeNode node;
  std::size_t slot = 0;
  std::uint32_t indices = 0;
};

struct PatchBatch {
  std::vector<GpuPatch> patches;
  std::vector<DrawElementsIndirectCommand> draws;  // baseInstance names the patch; slots of mostVertices / mostIndices
};

PatchBatch batchPatches(std::span<const PlacedNode> placed, const View& view, double radius, std::uint32_t mostVertices,
                        std::uint32_t mostIndices);

}  // namespace strata::bdam
