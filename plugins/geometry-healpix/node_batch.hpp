#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl/indirect_draw.hpp>

#include "healpix_frame.hpp"
#include "node_selection.hpp"

namespace strata::healpix {

// A node as the vertex shader reads it (plugins/geometry-healpix/healpix_surface.vert, std430): its centre's terms
// for the relative HEALPix inverse, and the centre itself from the eye and from the frame's reference, in
// double on the CPU before they become float, so that the GPU only adds small offsets
// (docs/architecture.md, "Precision").
struct GpuNode {
  HealpixFrame frame;             // the centre's terms (healpix_offset.glsl)
  glm::vec4 centreFromEye;        // xyz: m, planet-fixed, the centre on the body's sphere minus the eye; w: cell size
  glm::vec4 centreFromReference;  // xyz: unit vector of the centre minus View::reference's, east-north-up
                                  // there; w: the centre's longitude from the reference, in [-pi, pi]
  glm::vec4 centre;               // xyz: unit vector of the centre, planet-fixed
  glm::vec4 corner;               // x: the face; y, z: the face point of the node's corner 0, where heights
                                  // are sampled by face point (HealpixFaceLayer::faceSamplingFunction); w: 0
};

// A vertex on a node's outline, made on the CPU in double from its exact face point. A vertex two nodes share
// (neighbours of one level, or a coarser neighbour's vertex and a finer one's even vertex) is the same face
// point, in the same face or across a face edge, so both get the same float values and the same heights:
// computed in the shader relative to each node's own centre it would differ in the last bits, and a height
// layer sampled at float positions (source.procedural: 0.4 m steps on Earth) would open a crack there.
struct BoundaryVertex {
  glm::vec4 fromEye;        // xyz: m, planet-fixed, the point on the body's sphere minus the eye
  glm::vec4 fromReference;  // xyz: unit vector minus View::reference's, east-north-up there
  glm::vec4 normal;         // xyz: unit vector, planet-fixed
  glm::vec4 facePoint;      // x: the node's face; y, z: the face point (exact: dyadic)
};

// What a frame uploads: a node and a draw of the proxy grid each, the draw's index section chosen by the
// node's coarser edges (stitched_grid.hpp) and its baseInstance naming the node; and each node's 4 cells
// outline vertices, edge by edge from corner e towards corner e + 1 (healpix_node.hpp's numbering).
struct NodeBatch {
  std::vector<GpuNode> nodes;
  std::vector<DrawElementsIndirectCommand> draws;
  std::vector<BoundaryVertex> boundary;
};

NodeBatch batchNodes(std::span<const SelectedNode> selected, const View& view, double radius, int cells);

}  // namespace strata::healpix
