#include "simplex_noise.hpp"

#include <array>
#include <cmath>

namespace strata::procedural {
namespace {

// Skewing (simplex_noise.hpp): F = (sqrt(n + 1) - 1) / n and G = (1 - 1 / sqrt(n + 1)) / n for n = 3
// (Gustavson 2005, section 3).
constexpr double kSkew = kSimplexSkew;
constexpr double kUnskew = kSimplexUnskew;
// The squared radius of each corner's kernel (r0^2 - r^2)^4. 0.5 is the squared distance from a corner to
// the far faces of the tetrahedra around it, so a kernel dies out before a cell that does not sum it. The
// 0.6 of Perlin's and Gustavson's reference code reaches past them and leaves steps of up to 0.003 (in
// units of the field's range) where cells meet, which tests/procedural/simplex_noise_test.cpp detects.
constexpr double kKernelRadiusSquared = 0.5;
// Brings the field within [-1, 1]: the largest |sum| of the four kernels found by hill climbing from 12,000
// random starts is 0.013007, so 76 gives at most 0.9886 (the gradients' lengths of sqrt 2 included).
constexpr double kNormalisation = 76.0;

// Gradients toward the midpoints of a cube's 12 edges (Perlin 2002, section 3): no axis is favoured and
// a dot product needs no multiplications by irrational numbers.
constexpr std::array<glm::dvec3, 12> kGradients{{{1, 1, 0},
                                                 {-1, 1, 0},
                                                 {1, -1, 0},
                                                 {-1, -1, 0},
                                                 {1, 0, 1},
                                                 {-1, 0, 1},
                                                 {1, 0, -1},
                                                 {-1, 0, -1},
                                                 {0, 1, 1},
                                                 {0, -1, 1},
                                                 {0, 1, -1},
                                                 {0, -1, -1}}};

// Which gradient a lattice corner carries. The coordinates are folded with the large primes of Teschner
// et al. 2003 ("Optimized spatial hashing for collision detection"), then mixed by Wellons' lowbias32
// finaliser ("Prospecting for hash functions", 2018) so that neighbouring corners are uncorrelated.
// Unsigned arithmetic wraps identically in C++ and GLSL, which is what lets the two agree.
std::uint32_t gradientIndex(const glm::ivec3& corner, std::uint32_t seed) {
  std::uint32_t h = std::uint32_t(corner.x) * 73856093u ^ std::uint32_t(corner.y) * 19349663u ^
                    std::uint32_t(corner.z) * 83492791u ^ seed * 2654435761u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h % 12u;
}

// One corner's share at `offset` from it: its gradient's ramp, faded out radially.
double cornerContribution(const glm::dvec3& offset, const glm::ivec3& corner, std::uint32_t seed) {
  double fade = kKernelRadiusSquared - glm::dot(offset, offset);
  if (fade <= 0.0) return 0.0;
  fade *= fade;
  return fade * fade * glm::dot(kGradients[gradientIndex(corner, seed)], offset);
}

}  // namespace

double simplexNoise(const glm::dvec3& point, std::uint32_t seed) {
  const glm::dvec3 cellOrigin = glm::floor(point + (point.x + point.y + point.z) * kSkew);
  const glm::ivec3 cell(cellOrigin);
  const glm::dvec3 offset = point - (cellOrigin - (cellOrigin.x + cellOrigin.y + cellOrigin.z) * kUnskew);
  // The unit cube holds six tetrahedra, one per ordering of the offset's components; the one holding the
  // point steps from the cell origin along the axis of the largest component, then of the second largest.
  // Ties go to the lower axis, so the ranks are always a permutation of 0, 1, 2.
  const int xBeatsY = offset.x >= offset.y, xBeatsZ = offset.x >= offset.z, yBeatsZ = offset.y >= offset.z;
  const glm::ivec3 rank(xBeatsY + xBeatsZ, 1 - xBeatsY + yBeatsZ, 2 - xBeatsZ - yBeatsZ);
  const glm::ivec3 first(rank.x == 2, rank.y == 2, rank.z == 2);
  const glm::ivec3 second(rank.x >= 1, rank.y >= 1, rank.z >= 1);
  const double sum = cornerContribution(offset, cell, seed) +
                     cornerContribution(offset - glm::dvec3(first) + kUnskew, cell + first, seed) +
                     cornerContribution(offset - glm::dvec3(second) + 2.0 * kUnskew, cell + second, seed) +
                     cornerContribution(offset - 1.0 + 3.0 * kUnskew, cell + 1, seed);
  return kNormalisation * sum;
}

}  // namespace strata::procedural
