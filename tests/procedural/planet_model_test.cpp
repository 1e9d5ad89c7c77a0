// The planet model in double: heights within the amplitude, the footprint's octave limit, and a colour
// ramp whose contour lines appear wherever the height crosses a multiple of the interval.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "planet_model.hpp"

namespace strata::procedural {
namespace {

constexpr double kMarsRadius = 3396190.0;

glm::dvec3 randomNormal(std::mt19937_64& random) {
  std::normal_distribution<double> gaussian;
  return glm::normalize(glm::dvec3(gaussian(random), gaussian(random), gaussian(random)));
}

TEST(PlanetModel, HeightsStayWithinTheAmplitudeAndUseMuchOfIt) {
  const PlanetModel planet({}, kMarsRadius);
  std::mt19937_64 random(1);
  double lowest = 0.0, highest = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double height = planet.height(randomNormal(random));
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
  }
  const double amplitude = planet.parameters().amplitude;
  EXPECT_GE(lowest, -amplitude);
  EXPECT_LE(highest, amplitude);
  // Typical heights are a fifth of the amplitude; the deepest seas and highest peaks reach past 40% of it.
  EXPECT_LT(lowest, -0.4 * amplitude);
  EXPECT_GT(highest, 0.4 * amplitude);
}

TEST(PlanetModel, IsDeterministicPerSeed) {
  const PlanetModel planet({}, kMarsRadius), same({}, kMarsRadius), other({.seed = 7}, kMarsRadius);
  std::mt19937_64 random(2);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 normal = randomNormal(random);
    EXPECT_EQ(planet.height(normal), same.height(normal));
    differ += std::abs(planet.height(normal) - other.height(normal)) > 1.0;
  }
  EXPECT_GT(differ, 990);
}

TEST(PlanetModel, IsContinuousOverTheSurface) {
  const PlanetModel planet({}, kMarsRadius);
  std::mt19937_64 random(3);
  for (int i = 0; i < 10000; ++i) {
    const glm::dvec3 normal = randomNormal(random), nearby = glm::normalize(normal + 1e-9 * randomNormal(random));
    // 1e-9 of the radius is 3 mm; no slope of the planet reaches 10 (84 degrees) over it.
    EXPECT_NEAR(planet.height(normal), planet.height(nearby), 0.03);
  }
}

TEST(PlanetModel, ACoarserFootprintLeavesOutOnlyFineOctaves) {
  const PlanetModel planet({}, kMarsRadius);
  const PlanetParameters& p = planet.parameters();
  std::mt19937_64 random(4);
  const double footprint = 10000.0;  // m: a global raster of 2048 columns
  // The octaves that lose weight: wavelength / 2^k below 4 footprints, k >= log2(wavelength / 4 footprints).
  const int firstFaded = int(std::ceil(std::log2(p.wavelength / (4.0 * footprint))));
  const double total = (1.0 - std::pow(0.5, p.octaves)) / 0.5;
  const double bound = p.amplitude * 0.99 * (std::pow(0.5, firstFaded) - std::pow(0.5, p.octaves)) / 0.5 / total;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 normal = randomNormal(random);
    EXPECT_EQ(planet.height(normal, 0.0), planet.height(normal));
    EXPECT_LE(std::abs(planet.height(normal, footprint) - planet.height(normal)), bound);
  }
  EXPECT_DOUBLE_EQ(octaveWeight(0, p.wavelength, 1e9), 1.0);
  EXPECT_DOUBLE_EQ(octaveWeight(3, 8000.0, 250.0), 1.0);  // 1000 m wavelength, 4 footprints
  EXPECT_DOUBLE_EQ(octaveWeight(3, 8000.0, 500.0), 0.0);  // 2 footprints: the Nyquist limit
  EXPECT_DOUBLE_EQ(octaveWeight(3, 8000.0, 1000.0), 0.0);
}

double luminance(const glm::dvec3& colour) { return 0.2126 * colour.r + 0.7152 * colour.g + 0.0722 * colour.b; }

TEST(PlanetModel, ContourLinesAppearWhereverTheHeightCrossesAMultipleOfTheInterval) {
  const PlanetModel planet({}, kMarsRadius);
  const double interval = planet.parameters().contourInterval;
  // Along the equator in steps of 20 m: the height changes far less per step than a line is wide.
  const int steps = 200000;
  int crossings = 0, onLines = 0;
  double previous = planet.height({1.0, 0.0, 0.0});
  bool previousOnLine = planet.onContour(previous);
  for (int i = 1; i < steps; ++i) {
    const double angle = i * 20.0 / kMarsRadius;
    const double height = planet.height({std::cos(angle), std::sin(angle), 0.0});
    const bool onLine = planet.onContour(height);
    if (std::floor(height / interval) != std::floor(previous / interval)) {
      ++crossings;
      EXPECT_TRUE(onLine || previousOnLine) << "the height crossed a contour at " << angle << " rad without a line";
    }
    if (onLine) {
      ++onLines;
      EXPECT_LT(luminance(planet.colour(height)), 0.005);
    } else {
      EXPECT_GT(luminance(planet.colour(height)), 0.015) << "ramp colour at " << height << " m is too dark";
    }
    previous = height;
    previousOnLine = onLine;
  }
  EXPECT_GT(crossings, 20);
  // Lines are 16% of the interval in height, so they cover a share of the ground of about that.
  EXPECT_GT(onLines, steps / 20);
  EXPECT_LT(onLines, steps / 3);
}

TEST(PlanetModel, ColoursRunFromSeaToSnow) {
  const PlanetModel planet({}, kMarsRadius);
  // Halfway between contour lines, at a quarter of the amplitude down, a twentieth up and over half up.
  const double interval = planet.parameters().contourInterval;
  const glm::dvec3 sea = planet.colour(-3.5 * interval), lowland = planet.colour(0.5 * interval),
                   snow = planet.colour(7.5 * interval);
  EXPECT_GT(sea.b, sea.r);
  EXPECT_GT(sea.b, sea.g);
  EXPECT_GT(lowland.g, lowland.b);
  EXPECT_GT(snow.r, 0.8);
  EXPECT_GT(snow.g, 0.8);
}

}  // namespace
}  // namespace strata::procedural
