#include "planet_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "simplex_noise.hpp"

namespace strata::procedural {
namespace {

// The GPU sums the octaves in float (plugins/source-procedural/planet.glsl): near the frame's reference, where a
// centimetre shows, to a few ulps of each octave's amplitude, millimetres at the default 12 km. A hundred
// thousandth of the amplitude (12 cm) covers that by an order and is still small beside a metre up.
constexpr double kFloatSlack = 1e-5;

// How many of the first octaves every sample of footprint up to `footprint` m sums at full weight (at least
// the first, which always counts): the weights fall with the octave and rise as the footprint shrinks.
int octavesAtFullWeight(const PlanetParameters& planet, double footprint) {
  int full = 1;
  while (full < planet.octaves && octaveWeight(full, planet.wavelength, footprint) == 1.0) ++full;
  return full;
}

}  // namespace

// Each octave's noise lies within the noise at the cap's centre plus or minus its slope bound times the
// farthest the cap's normals reach from the centre's in its lattice (a chord of 2 sin(angle / 2) scaled), and
// within its reach. A sample sums octaves 0 to m - 1 at full weight and the next at a weight in [0, 1]
// (octaveWeight: one fading octave at a time), so its sum lies between two consecutive partial sums, and
// since no sample in the cap sums fewer than octavesAtFullWeight() at full weight, between the least and
// greatest of the partial sums from there on.
HeightBounds heightsWithin(const PlanetModel& planet, const glm::dvec3& centre, double angle) {
  const PlanetParameters& parameters = planet.parameters();
  const double reach = 2.0 * std::sin(0.5 * std::clamp(angle, 0.0, std::numbers::pi)) * planet.latticeUnitsPerNormal();
  const int fewest = octavesAtFullWeight(parameters, 2.0 * angle * planet.radius());
  double low = 0.0, high = 0.0, amplitude = 1.0;
  double least = std::numeric_limits<double>::infinity(), greatest = -least;
  for (int k = 0; k < parameters.octaves; ++k, amplitude *= kOctaveGain) {
    const double swing = kSimplexSlope * std::ldexp(reach, k);
    const double noise = swing < 2.0 * kSimplexReach ? planet.octaveNoise(k, centre) : 0.0;
    low += amplitude * std::max(-kSimplexReach, noise - swing);
    high += amplitude * std::min(kSimplexReach, noise + swing);
    if (k + 1 < fewest) continue;
    least = std::min(least, low);
    greatest = std::max(greatest, high);
  }
  const double slack = kFloatSlack * parameters.amplitude;
  return {planet.metresPerNoise() * least - slack, planet.metresPerNoise() * greatest + slack};
}

}  // namespace strata::procedural
