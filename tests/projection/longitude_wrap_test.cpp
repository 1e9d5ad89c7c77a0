// Projections that wrap around the body put longitudes within half a turn of the raster's centre
// (setLongitudeCentre), so that a raster spanning [0, 360) degrees, or one across the antimeridian, sees
// its own longitudes; by default the centre is the central meridian, as in PROJ.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/trigonometric.hpp>

#include "projection_cases.hpp"

namespace strata::test {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec2 forwardDegrees(const Projection& projection, double lon, double lat) {
  return *projection.forward(glm::radians(glm::dvec2(lon, lat)));
}

TEST(LongitudeWrap, GeographicRasterFrom0To360Degrees) {
  const auto projection = makeProjection("+proj=longlat", kMars);
  projection->setLongitudeCentre(kPi);
  EXPECT_NEAR(forwardDegrees(*projection, -10.0, 5.0).x, 350.0, 1e-12);
  EXPECT_NEAR(forwardDegrees(*projection, -180.0, 5.0).x, 180.0, 1e-12);
  EXPECT_NEAR(forwardDegrees(*projection, 0.0, 5.0).x, 0.0, 1e-12);
  EXPECT_NEAR(forwardDegrees(*projection, 359.5, 5.0).x, 359.5, 1e-12);
  EXPECT_NEAR(forwardDegrees(*projection, 360.0, 5.0).x, 0.0, 1e-12);  // [0, 360): the west edge
  EXPECT_NEAR(forwardDegrees(*projection, 370.0, 5.0).x, 10.0, 1e-12);
  EXPECT_NEAR(forwardDegrees(*projection, -10.0, 5.0).y, 5.0, 1e-12);
  EXPECT_NEAR(glm::degrees(projection->inverse({350.0, 5.0})->x), 350.0, 1e-12);
}

TEST(LongitudeWrap, ByDefaultAroundTheCentralMeridian) {
  const auto geographic = makeProjection("+proj=longlat", kMoon);
  EXPECT_NEAR(forwardDegrees(*geographic, 190.0, 0.0).x, -170.0, 1e-12);
  EXPECT_NEAR(forwardDegrees(*geographic, -180.0, 0.0).x, -180.0, 1e-12);
  const auto eqc = makeProjection("+proj=eqc +lon_0=180", kMoon);
  const double metresPerDegree = kMoon.semiMajorAxis * kPi / 180.0;
  EXPECT_NEAR(forwardDegrees(*eqc, -170.0, 0.0).x, 10.0 * metresPerDegree, 1e-6);
  EXPECT_NEAR(forwardDegrees(*eqc, 170.0, 0.0).x, -10.0 * metresPerDegree, 1e-6);
}

TEST(LongitudeWrap, EqcRasterAcrossTheAntimeridian) {
  const auto projection = makeProjection("+proj=eqc +lat_ts=30 +x_0=1000", kMars);
  projection->setLongitudeCentre(kPi);
  const double metresPerDegree = kMars.semiMajorAxis * std::cos(kPi / 6.0) * kPi / 180.0;
  EXPECT_NEAR(forwardDegrees(*projection, -175.0, 10.0).x, 185.0 * metresPerDegree + 1000.0, 1e-6);
  EXPECT_NEAR(forwardDegrees(*projection, 175.0, 10.0).x, 175.0 * metresPerDegree + 1000.0, 1e-6);
  EXPECT_NEAR(glm::degrees(projection->inverse({185.0 * metresPerDegree + 1000.0, 0.0})->x), 185.0, 1e-9);
  EXPECT_DOUBLE_EQ(projection->glslParameters()[0].y, kPi);  // the centre, relative to lon_0, for GLSL
}

TEST(LongitudeWrap, HealpixRasterFrom0To360Degrees) {
  const auto wrapped = makeProjection("+proj=healpix", kWgs84);
  const auto plain = makeProjection("+proj=healpix", kWgs84);
  wrapped->setLongitudeCentre(kPi);
  const double period = *plain->periodX();
  for (double lat : {0.0, 30.0, 60.0, -75.0, 90.0}) {
    // West of Greenwich the wrapped map is the plain one a period further east, polar triangles included.
    const glm::dvec2 west = forwardDegrees(*wrapped, -10.0, lat);
    EXPECT_NEAR(west.x, forwardDegrees(*plain, -10.0, lat).x + period, 1e-6) << lat;
    EXPECT_NEAR(west.y, forwardDegrees(*plain, -10.0, lat).y, 1e-6) << lat;
    EXPECT_NEAR(forwardDegrees(*wrapped, 10.0, lat).x, forwardDegrees(*plain, 10.0, lat).x, 1e-6) << lat;
    const auto back = wrapped->inverse(west);
    ASSERT_TRUE(back) << lat;
    if (lat != 90.0) {  // the pole is the tip of a triangle, at any longitude
      EXPECT_NEAR(glm::degrees(back->x), 350.0, 1e-9) << lat;
    }
  }
}

}  // namespace
}  // namespace strata::test
