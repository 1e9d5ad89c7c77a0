// The simplex noise in double: deterministic per seed, continuous across the lattice's cells and the
// tetrahedra inside them, within [-1, 1], and never steeper than its slope bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "simplex_noise.hpp"

namespace strata::procedural {
namespace {

glm::dvec3 randomPoint(std::mt19937_64& random) {
  std::uniform_real_distribution<double> coordinate(-1000.0, 1000.0);
  return {coordinate(random), coordinate(random), coordinate(random)};
}

TEST(SimplexNoise, IsTheSameForTheSameSeedAndUnrelatedForAnother) {
  std::mt19937_64 random(1);
  double sumProduct = 0.0, sumSquares = 0.0;
  const int samples = 20000;
  for (int i = 0; i < samples; ++i) {
    const glm::dvec3 p = randomPoint(random);
    EXPECT_EQ(simplexNoise(p, 7), simplexNoise(p, 7));
    sumProduct += simplexNoise(p, 7) * simplexNoise(p, 8);
    sumSquares += simplexNoise(p, 7) * simplexNoise(p, 7);
  }
  // Fields of neighbouring seeds are uncorrelated: the standard error of the correlation is 1/sqrt(20000).
  EXPECT_LT(std::abs(sumProduct / sumSquares), 0.03);
}

// Points just either side of a boundary, where the evaluation switches cells or tetrahedra, agree to within
// what the noise's gradient (partial derivatives under 7 per lattice unit) allows over the step. A kernel
// reaching past its corner's tetrahedra (Perlin's r^2 = 0.6) fails this by steps of up to 0.003.
void expectContinuousAcross(const glm::dvec3& onBoundary, const glm::dvec3& across) {
  const double step = 1e-9;
  EXPECT_NEAR(simplexNoise(onBoundary - step * across, 3), simplexNoise(onBoundary + step * across, 3), 1e-7)
      << "at " << onBoundary.x << "," << onBoundary.y << "," << onBoundary.z;
}

TEST(SimplexNoise, IsContinuousAcrossCellFaces) {
  std::mt19937_64 random(2);
  std::uniform_int_distribution<int> integer(-50, 50);
  std::uniform_real_distribution<double> real(-50.0, 50.0);
  for (int i = 0; i < 5000; ++i) {
    // A point whose skewed x is a whole number lies on a face of the skewed cubic lattice; undo the skew
    // (Gustavson 2005: unskewing subtracts (x + y + z) / 6).
    const glm::dvec3 skewed(integer(random), real(random), real(random));
    const glm::dvec3 point = skewed - (skewed.x + skewed.y + skewed.z) / 6.0;
    expectContinuousAcross(point, {1.0, 0.0, 0.0});
  }
}

TEST(SimplexNoise, IsContinuousAcrossTheTetrahedraInsideACell) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> real(-50.0, 50.0), within(0.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    // Offsets within the cell with equal x and y components: the face between two of its six tetrahedra.
    const glm::dvec3 cell = glm::floor(glm::dvec3(real(random), real(random), real(random)));
    const double shared = within(random);
    const glm::dvec3 skewed = cell + glm::dvec3(shared, shared, within(random));
    const glm::dvec3 point = skewed - (skewed.x + skewed.y + skewed.z) / 6.0;
    expectContinuousAcross(point, {1.0, -1.0, 0.0});
  }
}

TEST(SimplexNoise, StaysWithinPlusMinusOneAndUsesMostOfIt) {
  std::mt19937_64 random(4);
  double lowest = 0.0, highest = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double value = simplexNoise(randomPoint(random), 11);
    lowest = std::min(lowest, value);
    highest = std::max(highest, value);
  }
  EXPECT_GE(lowest, -kSimplexReach);
  EXPECT_LE(highest, kSimplexReach);
  EXPECT_LT(lowest, -0.8);
  EXPECT_GT(highest, 0.8);
}

// The slope bound that procedural height bounds rest on (simplex_noise.hpp): no difference quotient over a
// short step exceeds it, and the steepest found is within a factor of two of it, so the bound is not idle.
TEST(SimplexNoise, NeverSteeperThanItsSlopeBound) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> gaussian;
  double steepest = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const glm::dvec3 p = randomPoint(random);
    const glm::dvec3 step = 1e-6 * glm::normalize(glm::dvec3(gaussian(random), gaussian(random), gaussian(random)));
    steepest = std::max(steepest, std::abs(simplexNoise(p + step, 12) - simplexNoise(p, 12)) / 1e-6);
  }
  std::printf("steepest slope found: %.3f per lattice unit, bound %.3f\n", steepest, kSimplexSlope);
  EXPECT_LE(steepest, kSimplexSlope);
  EXPECT_GT(steepest, 0.5 * kSimplexSlope);
}

}  // namespace
}  // namespace strata::procedural
