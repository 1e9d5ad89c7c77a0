#pragma once
#include <array>

#include <glm/glm.hpp>

#include "cube_bintree.hpp"
#include "displaced_patch.hpp"

namespace strata::bdam {

// The triangle a bintree node's patch is displaced from [Cignoni et al. 2003, §4.2]: its corners' planetocentric
// positions P_i, in double, and normals N_i, from the node's corners on the cube (P_i on the sphere of `radius`, N_i
// the unit direction there). A point of the patch is
//   P(b) + h N(b),  P(b) = P0 + b1 (P1 - P0) + b2 (P2 - P0),  N(b) = N0 + b1 (N1 - N0) + b2 (N2 - N0)
// (N(b) not renormalised, as the paper's vertex program has it), so that along an edge only its two corners count
// and patches meeting there agree. On an edge (a barycentric 0, or b1 + b2 = 1) P(b) and N(b) are formed from the
// edge's two corners alone, from the lexicographically lesser one, so that the patches meeting there compute the same
// bits for a point of the lattice. Corner 0 is the node's right angle, 1 and 2 its hypotenuse's ends.
struct DisplacedTriangle {
  std::array<glm::dvec3, 3> corners;  // P_i, m
  std::array<glm::dvec3, 3> normals;  // N_i, unit

  glm::dvec3 flatPoint(double b1, double b2) const;
  glm::dvec3 normal(double b1, double b2) const;
  // P(b) + h N(b) of a stored vertex.
  glm::dvec3 point(const DisplacedVertex& vertex) const;
  // The displacement h along N(b) at which the point lies `distance` m from the body's centre: where the terrain
  // of that height meets the line through the flat point.
  double displacementTo(double b1, double b2, double distance) const;
  // The stored vertex nearest a planetocentric point: the barycentrics of the flat point on the line from the body's
  // centre through it, corrected for N(b)'s lean from that line, quantised, and the displacement that keeps the
  // point's distance from the centre. `edgeOpposite` (0, 1 or 2; -1 for none) names the edge the point is known to
  // lie on: it is put there from that edge's corners alone, so that the patches sharing the edge store it alike.
  DisplacedVertex vertexAt(const glm::dvec3& point, int edgeOpposite) const;
  // Whether the edge opposite corner `opposite` is formed from its higher-numbered corner (its lexicographically
  // lesser end), as point() forms it: what the GPU needs to form it alike (patch_batch.hpp).
  bool edgeRunsBackwards(int opposite) const;
};

DisplacedTriangle displacedTriangle(const BintreeNode& node, double radius);

}  // namespace strata::bdam
