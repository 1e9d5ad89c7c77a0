// The reference spheres (plugins/geometry-pgm/reference_spheres.hpp) against values derived independently from
// [Mahsman 2010, §3.4] (Eqs. 3.5, 3.6; b from §3.6.4), for Mars: r_p = 3396 km, r_max = 3417.2 km, lengths in
// km. The thesis prints no such values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cross_section.hpp"
#include "reference_spheres.hpp"

namespace strata::pgm {
namespace {

constexpr double kPrimary = 3396.0, kMaximum = 3417.2;

struct TableRow {
  double altitude, primaryTangent, outermost, secondary, secondaryTangent, blendStart;  // km, deg, deg, km, deg, deg
};

// The derived table as it was written down: angles to 1e-4 degree, the radius to 1e-3 km.
constexpr TableRow kTable[] = {
    {0.001, 89.9560, 6.4295, 3374.642, 83.5705, 80.9604}, {1, 88.6097, 7.7758, 3365.765, 82.2242, 79.7488},
    {10, 85.6084, 10.7771, 3345.925, 79.2229, 77.0476},   {100, 76.2630, 20.1225, 3282.601, 69.8775, 68.6367},
    {1000, 50.5808, 45.8047, 3064.477, 44.1953, 45.5227}, {5000, 23.8584, 72.5271, 2520.943, 17.4729, 21.4726},
    {20000, 8.3461, 88.0394, 800.445, 1.9606, 7.5115},
};

// Half a unit of the last printed digit, and a hair for the rounding of the comparison itself.
constexpr double kAngleDigit = 0.5e-4 + 1e-9, kRadiusDigit = 0.5e-3 + 1e-9;

TEST(PgmReferenceSpheres, EveryRowOfTheDigestsTable) {
  for (const TableRow& row : kTable) {
    SCOPED_TRACE(row.altitude);
    const double distance = kPrimary + row.altitude;
    const ReferenceSpheres spheres = referenceSpheres(distance, kPrimary, kMaximum);
    const CrossSection view = crossSection(distance, spheres.primary, spheres.secondary, 0.9);
    EXPECT_EQ(spheres.primary, kPrimary);
    EXPECT_NEAR(glm::degrees(view.primaryTangent), row.primaryTangent, kAngleDigit);
    EXPECT_NEAR(glm::degrees(outermostNormalAngle(distance, kPrimary, kMaximum)), row.outermost, kAngleDigit);
    EXPECT_NEAR(spheres.secondary, row.secondary, kRadiusDigit);
    EXPECT_NEAR(glm::degrees(view.secondaryTangent), row.secondaryTangent, kAngleDigit);
    EXPECT_NEAR(glm::degrees(view.blendStart), row.blendStart, kAngleDigit);
  }
}

// The secondary sphere's own tangent ray ends at gamma0: tau_s = pi/2 - gamma0 (Eq. 3.6).
TEST(PgmReferenceSpheres, TheSecondaryTangentEndsAtTheOutermostNormalAngle) {
  for (const TableRow& row : kTable) {
    const double distance = kPrimary + row.altitude;
    const ReferenceSpheres spheres = referenceSpheres(distance, kPrimary, kMaximum);
    EXPECT_NEAR(tangentAngle(distance, spheres.secondary),
                0.5 * std::numbers::pi - outermostNormalAngle(distance, kPrimary, kMaximum), 1e-12);
  }
}

// r_s = d cos(gamma0) ([Mahsman 2010, §3.4.2, Eq. 3.6]) is 0 at d = r_p / sqrt(1 - (r_p/r_max)^2) = 30534.76 km;
// beyond, none.
TEST(PgmReferenceSpheres, TheSecondarySphereVanishesFarAway) {
  const double vanishing = kPrimary / std::sqrt(1.0 - (kPrimary / kMaximum) * (kPrimary / kMaximum));
  EXPECT_NEAR(vanishing, 30534.76, 0.01);
  EXPECT_GT(referenceSpheres(vanishing - 1.0, kPrimary, kMaximum).secondary, 0.0);
  EXPECT_EQ(referenceSpheres(vanishing + 1.0, kPrimary, kMaximum).secondary, 0.0);
  EXPECT_EQ(referenceSpheres(1e6, kPrimary, kMaximum).secondary, 0.0);
}

// Without room above the primary sphere, gamma0 is the primary horizon and the secondary sphere is the
// primary one.
TEST(PgmReferenceSpheres, AMaximumSphereAtThePrimaryOneAddsNothing) {
  const double distance = kPrimary + 100.0;
  const double horizon = 0.5 * std::numbers::pi - tangentAngle(distance, kPrimary);
  EXPECT_NEAR(outermostNormalAngle(distance, kPrimary, kPrimary), horizon, 1e-12);
  EXPECT_NEAR(referenceSpheres(distance, kPrimary, kPrimary).secondary, kPrimary, 1e-9);
}

// A primary radius from the previous frame may reach the eye or beyond it (the eye dropped below the
// lowest terrain seen): it is kept just below the eye, where every sum stays finite.
TEST(PgmReferenceSpheres, ThePrimaryRadiusStaysBelowTheEye) {
  const double distance = kPrimary + 0.5;
  for (double wanted : {kPrimary + 0.5, kPrimary + 2.0}) {
    const ReferenceSpheres spheres = referenceSpheres(distance, wanted, kMaximum);
    EXPECT_LT(spheres.primary, distance);
    EXPECT_NEAR(spheres.primary, distance * (1.0 - kLeastAltitudeFraction), 1e-9);
    EXPECT_TRUE(std::isfinite(spheres.secondary));
    EXPECT_GT(spheres.secondary, 0.0);
  }
  EXPECT_EQ(clampPrimaryRadius(kPrimary, distance), kPrimary);
}

}  // namespace
}  // namespace strata::pgm
