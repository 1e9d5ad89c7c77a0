#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl/indirect_draw.hpp>

#include "healpix_frame.hpp"
#include "node_selection.hpp"

namespace strata::healpix {

// A node as the vertex shader reads it (shaders/geometry/healpix_surface.vert, std430): its centre's terms
// for the relative HEALPix inverse, and the centre itself from the eye and from the frame's reference, in
// double on the CPU before they become float, so that the GPU only adds small offsets (DESIGN.md, Precision).
struct GpuNode {
  HealpixFrame frame;             // the centre's terms (healpix_offset.glsl)
  glm::vec4 centreFromEye;        // xyz: m, planet-fixed, the centre on the body's sphere minus the eye; w: cell size
  glm::vec4 centreFromReference;  // xyz: unit vector of the centre minus View::reference's, east-north-up
                                  // there; w: the centre's longitude from the reference, in [-pi, pi]
  glm::vec4 centre;               // xyz: unit vector of the centre, planet-fixed
};

// What a frame uploads: a node and a draw of the proxy grid each, the draw's index section chosen by the
// node's coarser edges (stitched_grid.hpp) and its baseInstance naming the node.
struct NodeBatch {
  std::vector<GpuNode> nodes;
  std::vector<DrawElementsIndirectCommand> draws;
};

NodeBatch batchNodes(std::span<const SelectedNode> selected, const View& view, double radius, int cells);

}  // namespace strata::healpix
