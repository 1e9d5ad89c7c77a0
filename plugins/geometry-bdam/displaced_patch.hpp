#pragma once
#include <cstdint>
#include <vector>

namespace strata::bdam {

// A patch of P-BDAM [Cignoni et al. 2003, §4.2]: an arbitrary triangulation of points on a displaced triangle,
// whose three corners (planetocentric positions in double, normals, texture coordinates) the bintree node holds.
// Each interior point is two barycentric coordinates and an offset along the corners' interpolated normal:
//   N(b) = N0 + b1 (N1 - N0) + b2 (N2 - N0)
//   P(b) = P0 + b1 (P1 - P0) + b2 (P2 - P0) + h N(b)
// Barycentrics are kept in steps of 1/4096 (§4.4's 12 bits, "sufficient to encode over 16M positions in a
// triangular patch", and one value more, so that an edge's halves, quarters and so on down to its 4096ths are exact:
// a child's corners and every leaf grid point lie on the lattice of each coarser patch) and displacements to
// centimetres (the paper's vertex program unpacks h in steps of 0.01 m,
// §4.2, Fig. 5), so that what a patch holds is exactly what its file stores.
inline constexpr int kBarycentricSteps = 4096;  // b = steps / 4096: dyadic, so that corners and midpoints are exact

struct DisplacedVertex {
  std::uint16_t b1 = 0, b2 = 0;  // of corners 1 and 2, in steps of 1 / kBarycentricSteps; corner 0's is the rest
  std::int32_t centimetres = 0;  // along the interpolated normal: +-21,474 km, beyond any body's relief
  bool operator==(const DisplacedVertex&) const = default;
};

struct DisplacedPatch {
  std::vector<DisplacedVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles, three indices each
  bool operator==(const DisplacedPatch&) const = default;
};

// The vertex at barycentrics `b1`, `b2` (each in [0, 1], their sum at most 1) displaced `metres`, quantised: b2 to the
// nearest step and b1 to the nearest that keeps the sum within the triangle, so that a point on the edge opposite
// corner 0 (b1 + b2 = 1) stays exactly on it, as the neighbour across that edge has it. Throws std::invalid_argument
// for a displacement beyond +-21,474 km.
DisplacedVertex displacedVertex(double b1, double b2, double metres);

// Throws std::invalid_argument naming the first vertex or index that breaks the form: barycentrics beyond the
// triangle (b1 + b2 over kBarycentricSteps), an index count not a multiple of three, an index past the vertices.
void checkPatch(const DisplacedPatch& patch);

}  // namespace strata::bdam
