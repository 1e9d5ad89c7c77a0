#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace strata::procedural {

// Three-dimensional simplex noise (Perlin 2002, "Improving noise"; explained by Gustavson 2005, "Simplex
// noise demystified"): a smooth pseudo-random field with features about one lattice unit across, in about
// [-1, 1]. Each `seed` gives an unrelated field. The lattice hash is integer arithmetic modulo 2^32, so
// shaders/procedural/simplex_noise.glsl, which mirrors this file in float, picks the same gradients.
double simplexNoise(const glm::dvec3& point, std::uint32_t seed);

// Skewing along the main diagonal turns the lattice of tetrahedra into the cubic lattice Z^3 (x + (x.x +
// x.y + x.z) kSimplexSkew) and back (x - (x.x + x.y + x.z) kSimplexUnskew).
inline constexpr double kSimplexSkew = 1.0 / 3.0;
inline constexpr double kSimplexUnskew = 1.0 / 6.0;

}  // namespace strata::procedural
