#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace strata::procedural {

// What makes one procedural planet, with defaults for a Mars-sized body.
struct PlanetParameters {
  // Which planet: every seed gives an unrelated height field. 2008, the year of [Kooima 2008], for no other
  // reason.
  std::uint32_t seed = 2008;
  // m. |height| never exceeds it (the noise stays within +-0.99); a typical height is a fifth of it, so
  // 12 km gives Mars-like relief: heights of 2.5 km root mean square, basins and peaks to about 8.5 km.
  double amplitude = 12000.0;
  // m: the lattice spacing of the first octave, the size of the largest features. 3000 km gives a Mars-sized
  // body continents and seas a few thousand kilometres across.
  double wavelength = 3.0e6;
  // Octaves summed, each half the wavelength of the one before: 12 reach 3000 km / 2^11 = 1.5 km.
  int octaves = 12;
  // m between contour lines: about 10 across the usual heights, each a hard edge that shows how a
  // projection sampled it.
  double contourInterval = 1000.0;
};

// Each octave's amplitude is half the one before, as its wavelength is: the sum is fractional Brownian
// motion with slopes alike at every scale (Mandelbrot 1982; Musgrave et al. 1989), as terrain tends to be.
inline constexpr double kOctaveGain = 0.5;

// Moves each octave's lattice off the one before. Without it every octave's lattice points would fall on
// the first octave's (2^k times a lattice point is one), where simplex noise is zero, and all octaves would
// vanish together there. Octave k samples the noise at 2^k R / wavelength times the unit normal, plus k times
// this (planet_lattice.hpp takes those points apart about the frame's reference).
inline constexpr glm::dvec3 kOctaveShift(0.6180339887, 0.3819660113, 0.2360679775);

// The demonstration planet of [Kooima 2008, ch. 4]: false data, a fractal sum of 3D
// simplex noise over the unit sphere, "observed" through several projections and resolutions. Heights and
// colours are computed in double here; plugins/source-procedural/planet.glsl does the same in float.
class PlanetModel {
 public:
  PlanetModel(const PlanetParameters& parameters, double radius);

  // Height in metres above the sphere at every octave.
  double height(const glm::dvec3& unitNormal) const;
  // Height as a sample `footprint` metres across sees it: octaves too fine for it are left out, so that it
  // does not alias (footprint 0: every octave).
  double height(const glm::dvec3& unitNormal, double footprint) const;
  // Linear RGB of a height: sea, lowland, highland, rock and snow, with dark contour lines.
  glm::dvec3 colour(double height) const;
  // Octave `octave`'s noise (within +-kSimplexReach) at a unit normal, unweighted.
  double octaveNoise(int octave, const glm::dvec3& unitNormal) const;
  // Lattice units of the first octave per unit of the normal: the first octave's features are `wavelength`
  // metres across; octave k's lattice is 2^k times as fine.
  double latticeUnitsPerNormal() const;
  // Metres of height per unit of the octaves' weighted sum of noise: the amplitude over the sum of every
  // octave's amplitude, so that leaving fine octaves out keeps the coarse heights where they were.
  double metresPerNoise() const;
  // Whether a height lies on a contour line.
  bool onContour(double height) const;
  // Metres of height from `height` to the nearest step of colour (an edge of a contour line; the coast is
  // one): a sample whose height is less certain than this may show either colour.
  double distanceToColourStep(double height) const;

  const PlanetParameters& parameters() const { return parameters_; }
  double radius() const { return radius_; }

 private:
  double distanceToContour(double height) const;

  PlanetParameters parameters_;
  double radius_;
};

// How much of octave `octave` a sample `footprint` metres across takes in (0 to 1). An octave counts fully
// while its lattice spacing is at least 4 footprints and fades out by 2 (the Nyquist limit: the noise
// has little energy above one cycle per lattice unit); the first octave always counts.
double octaveWeight(int octave, double wavelength, double footprint);

}  // namespace strata::procedural
