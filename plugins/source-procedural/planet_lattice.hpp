#pragma once
// The procedural planet's noise lattice about the frame's reference (View::reference), for sampling it
// relative to that point (issue 27): octave k's noise point of the reference's normal, 2^k R / wavelength
// times it plus octave k's shift (planet_model.cpp), taken apart in double into an integer skewed cell of
// the simplex lattice and a small remainder, so that the GPU adds each sample's own small offset to the
// remainder alone (plugins/source-procedural/planet.glsl, planetHeightAt). In float the whole point resolves
// 0.4 m of ground on Earth at the default wavelength; the remainder micrometres.
#include <array>

#include <glm/glm.hpp>

#include "planet_model.hpp"

namespace strata::procedural {

inline constexpr int kLatticeOctaves = 24;  // the most octaves a planet sums (source.procedural's `octaves`)

struct PlanetLattice {
  std::array<glm::ivec3, kLatticeOctaves> anchor{};
  std::array<glm::dvec3, kLatticeOctaves> local{};
  int octaves = 0;                // those whose anchor fits in an int: the finest of a tiny wavelength may not
  glm::dmat3 frame{1.0};          // columns: east, north, up of the reference
  glm::dvec2 latitude{0.0, 1.0};  // sin and cos of the reference's
};

PlanetLattice planetLattice(const PlanetParameters& planet, double radius, glm::dvec2 referenceLonlat);

}  // namespace strata::procedural
