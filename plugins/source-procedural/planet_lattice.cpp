#include "planet_lattice.hpp"

#include <cmath>

#include "simplex_noise.hpp"

namespace strata::procedural {
namespace {

// Anchors stay well inside an int, so that anchor + a few cells does not overflow on the GPU either.
constexpr double kLargestAnchor = 1 << 30;

glm::dvec3 unitNormalOf(glm::dvec2 lonlat) {
  return {std::cos(lonlat.y) * std::cos(lonlat.x), std::cos(lonlat.y) * std::sin(lonlat.x), std::sin(lonlat.y)};
}

}  // namespace

PlanetLattice planetLattice(const PlanetParameters& planet, double radius, glm::dvec2 referenceLonlat) {
  PlanetLattice lattice;
  const double sinLon = std::sin(referenceLonlat.x), cosLon = std::cos(referenceLonlat.x);
  lattice.latitude = {std::sin(referenceLonlat.y), std::cos(referenceLonlat.y)};
  const glm::dvec3 east(-sinLon, cosLon, 0.0), up = unitNormalOf(referenceLonlat);
  lattice.frame = glm::dmat3(east, glm::cross(up, east), up);
  const glm::dvec3 point = up * (radius / planet.wavelength);
  for (int k = 0; k < planet.octaves && k < kLatticeOctaves; ++k) {
    const glm::dvec3 noisePoint = std::ldexp(1.0, k) * point + double(k) * kOctaveShift;
    const glm::dvec3 cell = glm::floor(noisePoint + (noisePoint.x + noisePoint.y + noisePoint.z) * kSimplexSkew);
    if (glm::any(glm::greaterThan(glm::abs(cell), glm::dvec3(kLargestAnchor)))) break;
    lattice.anchor[std::size_t(k)] = glm::ivec3(cell);
    lattice.local[std::size_t(k)] = noisePoint - (cell - (cell.x + cell.y + cell.z) * kSimplexUnskew);
    lattice.octaves = k + 1;
  }
  return lattice;
}

}  // namespace strata::procedural
