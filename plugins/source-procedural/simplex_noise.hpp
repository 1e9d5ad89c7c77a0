#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace strata::procedural {

// Three-dimensional simplex noise (Perlin 2002, "Improving noise"; explained by Gustavson 2005, "Simplex
// noise demystified"): a smooth pseudo-random field with features about one lattice unit across, in about
// [-1, 1]. Each `seed` gives an unrelated field. The lattice hash is integer arithmetic modulo 2^32, so
// plugins/source-procedural/simplex_noise.glsl, which mirrors this file in float, picks the same gradients.
double simplexNoise(const glm::dvec3& point, std::uint32_t seed);

// Skewing along the main diagonal turns the lattice of tetrahedra into the cubic lattice Z^3 (x + (x.x +
// x.y + x.z) kSimplexSkew) and back (x - (x.x + x.y + x.z) kSimplexUnskew).
inline constexpr double kSimplexSkew = 1.0 / 3.0;
inline constexpr double kSimplexUnskew = 1.0 / 6.0;

// |simplexNoise| never exceeds it: 76 times the largest sum of the four kernels, 0.013007 (simplex_noise.cpp).
inline constexpr double kSimplexReach = 0.9886;
// The field's slope never exceeds it, per lattice unit. A corner's kernel (0.5 - r^2)^4 (g . r) has a gradient
// of at most |g| (0.5 - r^2)^3 (0.5 + 7 r^2), 0.0787 |g| at r^2 = 1/14; the sum of that bound over the four
// corners of a tetrahedron peaks at 0.110626 (on a grid of 800 steps a side over the tetrahedron, the same to
// six digits on one of 400), times sqrt 2 (|g|) and 76: 11.89. Rounded up.
inline constexpr double kSimplexSlope = 11.9;

}  // namespace strata::procedural
