#include "planet_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "simplex_noise.hpp"

namespace strata::procedural {
namespace {

// A colour ramp: heights as fractions of the amplitude, colours in linear RGB, linear in between.
struct ColourStop {
  double height;
  glm::dvec3 colour;
};
// Sea: deep blue to shallow; land: green lowland, brown highland, grey rock, white snow (the highest 1% of
// the surface). The coast is a hard edge between the two.
const std::array<ColourStop, 2> kSea{{{-0.5, {0.004, 0.015, 0.08}}, {0.0, {0.03, 0.18, 0.42}}}};
const std::array<ColourStop, 4> kLand{
    {{0.0, {0.05, 0.20, 0.03}}, {0.2, {0.38, 0.24, 0.07}}, {0.4, {0.22, 0.18, 0.15}}, {0.5, {0.85, 0.87, 0.90}}}};
// Contour lines: nearly black, a contrast of 10:1 or more against every ramp colour but the deepest sea
// (4:1), and 16% of the interval wide in height: at a global raster's 10 km pixels that is a line about a
// pixel wide, whose shape shows how each projection sampled it.
const glm::dvec3 kContourColour(0.004, 0.004, 0.004);
constexpr double kContourHalfWidth = 0.08;

template <std::size_t N>
glm::dvec3 ramp(const std::array<ColourStop, N>& stops, double height) {
  if (height <= stops.front().height) return stops.front().colour;
  for (std::size_t i = 1; i < N; ++i)
    if (height < stops[i].height)
      return glm::mix(stops[i - 1].colour, stops[i].colour,
                      (height - stops[i - 1].height) / (stops[i].height - stops[i - 1].height));
  return stops.back().colour;
}

}  // namespace

double octaveWeight(int octave, double wavelength, double footprint) {
  if (octave == 0 || footprint <= 0.0) return 1.0;
  const double octaveWavelength = std::ldexp(wavelength, -octave);
  return std::clamp(std::log2(octaveWavelength / (2.0 * footprint)), 0.0, 1.0);
}

PlanetModel::PlanetModel(const PlanetParameters& parameters, double radius)
    : parameters_(parameters), radius_(radius) {}

double PlanetModel::height(const glm::dvec3& unitNormal) const { return height(unitNormal, 0.0); }

double PlanetModel::height(const glm::dvec3& unitNormal, double footprint) const {
  double sum = 0.0, amplitude = 1.0;
  for (int k = 0; k < parameters_.octaves; ++k, amplitude *= kOctaveGain) {
    const double weight = octaveWeight(k, parameters_.wavelength, footprint);
    if (weight == 0.0) break;  // and so are all finer octaves
    sum += weight * amplitude * octaveNoise(k, unitNormal);
  }
  return metresPerNoise() * sum;
}

double PlanetModel::octaveNoise(int octave, const glm::dvec3& unitNormal) const {
  // seed * 32 + k: a field of its own for every seed and octave (octaves are at most 24).
  const std::uint32_t seed = parameters_.seed * 32u + std::uint32_t(octave);
  return simplexNoise(std::ldexp(latticeUnitsPerNormal(), octave) * unitNormal + double(octave) * kOctaveShift, seed);
}

double PlanetModel::latticeUnitsPerNormal() const { return radius_ / parameters_.wavelength; }

double PlanetModel::metresPerNoise() const {
  const double total = (1.0 - std::pow(kOctaveGain, parameters_.octaves)) / (1.0 - kOctaveGain);
  return parameters_.amplitude / total;
}

// Metres from `height` to the nearest multiple of the contour interval.
double PlanetModel::distanceToContour(double height) const {
  const double interval = parameters_.contourInterval;
  return std::abs(height - interval * std::floor(height / interval + 0.5));
}

bool PlanetModel::onContour(double height) const {
  return distanceToContour(height) < kContourHalfWidth * parameters_.contourInterval;
}

double PlanetModel::distanceToColourStep(double height) const {
  // The coast lies on the contour at 0 m, so contour edges are the only steps; the ramp is continuous.
  return std::abs(distanceToContour(height) - kContourHalfWidth * parameters_.contourInterval);
}

glm::dvec3 PlanetModel::colour(double height) const {
  if (onContour(height)) return kContourColour;
  const double relative = height / parameters_.amplitude;
  return relative < 0.0 ? ramp(kSea, relative) : ramp(kLand, relative);
}

}  // namespace strata::procedural
