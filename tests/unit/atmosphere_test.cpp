// The Earth's atmosphere of [Bruneton 2008] in double: its optical depths against their closed form, the
// transmittance table against the quadrature it stores, and the sky's colours where physics puts them.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <strata/atmosphere_tables.hpp>

namespace strata {
namespace {

constexpr double kGround = 6360000.0;  // [Bruneton 2008]: Rg = 6360 km

const AtmosphereModel& earth() {
  static const AtmosphereModel model(Atmosphere{}, kGround);
  return model;
}

const AtmosphereTables& earthTables() {
  static const AtmosphereTables tables = makeAtmosphereTables(earth());
  return tables;
}

// Straight up through air of density exp(-h / H), the optical depth is beta H (1 - exp(-thickness / H)). The
// midpoint rule's error, (step / H)^2 / 24 of it, is under 3e-5 for the aerosols' 1.2 km in 2,000 steps of 30 m.
TEST(Atmosphere, VerticalOpticalDepthIsTheClosedForm) {
  const Atmosphere air;
  const auto closedForm = [&](double beta, double height) {
    return beta * height * (1.0 - std::exp(-air.thickness / height));
  };
  const glm::dvec3 depth = earth().opticalDepth(kGround, 1.0, air.thickness, 2000);
  const double aerosols = closedForm(air.mieExtinction, air.mieScaleHeight);
  for (int c = 0; c < 3; ++c) {
    const double expected = closedForm(air.rayleighScattering[c], air.rayleighScaleHeight) + aerosols;
    EXPECT_NEAR(depth[c], expected, expected * 3e-5) << "channel " << c;
  }
  // The molecules' vertical optical depth at 550 nm the model implies: 13.5e-6/m x 8 km.
  EXPECT_NEAR(closedForm(air.rayleighScattering.g, air.rayleighScaleHeight), 0.1079, 1e-4);
}

// The table's coordinates and the ray they stand for turn into each other, from the ground to the top of the air
// and from the zenith to the horizon.
TEST(Atmosphere, TransmittanceCoordinatesRoundTrip) {
  for (double altitude : {0.0, 1.0, 2000.0, 30000.0, 59999.0})
    for (double x : {0.0, 0.001, 0.25, 0.5, 0.9, 0.999, 1.0}) {
      const double r = kGround + altitude;
      const glm::dvec2 ray = rayOfTransmittanceCoordinates(earth(), transmittanceCoordinates(earth(), r, 0.0));
      EXPECT_NEAR(ray.x, r, 1e-6) << "altitude " << altitude;
      const glm::dvec2 unit(x, transmittanceCoordinates(earth(), r, 0.0).y);
      const glm::dvec2 back = rayOfTransmittanceCoordinates(earth(), unit);
      EXPECT_NEAR(transmittanceCoordinates(earth(), back.x, back.y).x, x, 1e-6) << "altitude " << altitude;
    }
  EXPECT_NEAR(transmittanceCoordinates(earth(), kGround + 1000.0, 1.0).x, 0.0, 1e-12);  // the zenith
}

// The table against the quadrature it stores (500 midpoints there, 4,000 here), between its points, at rays from
// the ground to the top of the air and from the zenith to just above the horizon: within 0.001. Bilinear reading of
// the 256 x 64 table leaves 3e-4 at worst here, where transmittance changes fastest, near the horizon.
TEST(Atmosphere, TransmittanceTableHoldsTheQuadrature) {
  double worst = 0.0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double r = kGround + 60000.0 * std::pow((j + 0.37) / 40.0, 2.0);
      const double horizon = -std::sqrt(1.0 - kGround * kGround / (r * r));
      const double mu = horizon + (1.0 - horizon) * std::pow((i + 0.61) / 40.0, 2.0);
      const glm::dvec3 expected = earth().transmittanceToTop(r, mu, 4000);
      const glm::dvec3 read = earthTables().transmittanceToTop(earth(), r, mu);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(read[c] - expected[c]));
    }
  EXPECT_LT(worst, 0.001);
}

// The sun's light straight down reaches the ground through 0.108 of the molecules' depth at 550 nm and 0.0053 of
// the aerosols': 89 per cent; at the horizon blue is lost first, so the low sun is red.
TEST(Atmosphere, SunlightReddensTowardTheHorizon) {
  const glm::dvec3 overhead = earthTables().transmittanceToTop(earth(), kGround, 1.0);
  EXPECT_NEAR(overhead.g, std::exp(-(0.1079 + 0.00533)), 0.002);
  const glm::dvec3 low = earthTables().transmittanceToTop(earth(), kGround, 0.0);
  EXPECT_GT(low.r, 2.0 * low.g);
  EXPECT_GT(low.g, 10.0 * low.b);
}

// Looking up from the ground with the sun 45 degrees high, the sky is blue: more blue than green than red.
// Looking along the ground toward a sun just set, the air over the horizon is red and the zenith still blue.
TEST(Atmosphere, TheSkyIsBlueByDayAndRedAtSunset) {
  const glm::dvec3 eye(0.0, 0.0, kGround + 2.0);
  const double s45 = std::sqrt(0.5);
  const AirLight zenith = airLightAlong(earth(), earthTables(), eye, {0.0, 0.0, 1.0}, 1e30, {s45, 0.0, s45}, 200, 100);
  EXPECT_GT(zenith.inscattered.b, zenith.inscattered.g);
  EXPECT_GT(zenith.inscattered.g, zenith.inscattered.r);
  const glm::dvec3 sunset = glm::normalize(glm::dvec3(1.0, 0.0, 0.01));
  const AirLight towardSun =
      airLightAlong(earth(), earthTables(), eye, glm::normalize(glm::dvec3(1.0, 0.0, 0.02)), 1e30, sunset, 400, 200);
  EXPECT_GT(towardSun.inscattered.r, towardSun.inscattered.b);
}

// Light scattered twice and more fills the planet's shadow by twilight: under a sun 3 degrees below the horizon
// the ground's air holds some, and more by day.
TEST(Atmosphere, MultipleScatteringLightsTheTwilight) {
  const double below = std::sin(glm::radians(-3.0));
  const glm::dvec3 twilight = earthTables().multipleScatteringAt(earth(), kGround, below);
  const glm::dvec3 day = earthTables().multipleScatteringAt(earth(), kGround, 0.7);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(twilight[c], 0.0);
    EXPECT_GT(day[c], twilight[c]);
  }
}

// The multiple-scattering table against its definition summed 64 times finer (64 x 64 directions, 100 steps along
// each), from the ground to 30 km, between the table's points. By day (the sun 17 degrees up and more) within 7%:
// the table's 128 directions leave up to 6%. Around the terminator Psi_ms falls a hundredfold within 0.1 of the
// sun's cosine and bilinear reading misses it by a share of itself but not of the day's light: within 1.5% of
// Psi_ms under an overhead sun (1.3% at worst).
TEST(Atmosphere, MultipleScatteringTableHoldsItsDefinition) {
  for (double altitude : {0.0, 5000.0, 30000.0}) {
    const double r = kGround + altitude;
    const glm::dvec3 overhead = multipleScatteringFor(earth(), earthTables(), r, 1.0, {64, 64, 100});
    for (double muSun : {-0.1, 0.0, 0.3, 0.7, 1.0}) {
      const glm::dvec3 fine = multipleScatteringFor(earth(), earthTables(), r, muSun, {64, 64, 100});
      const glm::dvec3 read = earthTables().multipleScatteringAt(earth(), r, muSun);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(read[c], fine[c], muSun >= 0.3 ? 0.07 * fine[c] : 0.015 * overhead[c])
            << "altitude " << altitude << ", sun's cosine " << muSun << ", channel " << c;
    }
  }
}

}  // namespace
}  // namespace strata
