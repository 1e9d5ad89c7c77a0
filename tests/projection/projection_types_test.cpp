// The built-in projection types: their declarations, what create() declines (nullptr: a variant the type does
// not handle) and refuses (strata::Error with a fix: values out of range), periods, and GLSL sides.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <strata/error.hpp>
#include <strata/gl/shader_library.hpp>

#include "projection/builtin_projections.hpp"
#include "projection_cases.hpp"

namespace strata::test {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ProjectionTypes, DeclareEachTypeAndProjNameOnce) {
  std::set<std::string> types, projNames;
  for (const ProjectionDeclaration& declaration : builtinProjections()) {
    EXPECT_TRUE(types.insert(declaration.type).second) << declaration.type;
    EXPECT_FALSE(declaration.summary.empty()) << declaration.type;
    EXPECT_TRUE(declaration.create) << declaration.type;
    for (const std::string& projName : declaration.projNames) EXPECT_TRUE(projNames.insert(projName).second);
  }
  EXPECT_EQ(types, (std::set<std::string>{"equirectangular", "polar-stereographic", "healpix", "orthographic",
                                          "perspective"}));
}

TEST(ProjectionTypes, DeclineVariantsTheyDoNotHandle) {
  for (const std::string terms :
       {"+proj=stere +lat_0=45", "+proj=stere", "+proj=healpix +rot_xy=30", "+proj=ortho +k_0=2", "+proj=eqc +units=km",
        "+proj=longlat +pm=paris", "+proj=nsper +h=1000 +axis=neu", "+proj=stere +lat_0=90 +to_meter=0.3048"})
    EXPECT_EQ(makeProjection(terms, kWgs84), nullptr) << terms;
}

void expectRefused(const std::string& terms, const Ellipsoid& ellipsoid, const std::string& named) {
  try {
    makeProjection(terms, ellipsoid);
    ADD_FAILURE() << "no error for '" << terms << "'";
  } catch (const Error& error) {
    EXPECT_NE(error.problem().find(named), std::string::npos) << error.what();
    EXPECT_FALSE(error.fix().empty()) << error.what();
  }
}

TEST(ProjectionTypes, RefuseValuesOutOfRange) {
  expectRefused("+proj=stere +lat_0=90 +lat_ts=100", kWgs84, "+lat_ts=100");
  expectRefused("+proj=stere +lat_0=90 +lat_ts=-71", kWgs84, "+lat_ts=-71");  // true scale across the equator
  expectRefused("+proj=stere +lat_0=-90 +k_0=0", kMars, "+k_0=0");
  expectRefused("+proj=stere +lat_0=95", kMars, "+lat_0=95");
  expectRefused("+proj=ups", kMars, "sphere");
  expectRefused("+proj=eqc +lat_ts=90", kMoon, "+lat_ts=90");  // no extent in x, and x / cos(lat_ts) divides by 0
  expectRefused("+proj=eqc +lat_0=-91", kMoon, "+lat_0=-91");
  expectRefused("+proj=nsper +h=0", kMars, "+h=0");
  expectRefused("+proj=tpers +h=-5", kMars, "+h=-5");
  expectRefused("+proj=tpers +h=1000 +tilt=90", kMars, "+tilt=90");
  expectRefused("+proj=ortho +lat_0=abc", kMars, "+lat_0=abc");
  expectRefused("+proj=healpix", Ellipsoid{0.0, 0.0}, "semi-major axis");
  expectRefused("+proj=healpix", Ellipsoid{6378137.0, 0.5}, "flattening");
}

// True scale at the equator is a polar stereographic map like any other (scale 1/2 at the pole on a
// sphere): Snyder's m_c / t_c is 1 / 1 there, and PROJ accepts it (compared in AgainstProj).
TEST(ProjectionTypes, AcceptTrueScaleAtTheEquatorForPolarStereographic) {
  const auto projection = makeProjection("+proj=stere +lat_0=90 +lat_ts=0", kMars);
  ASSERT_NE(projection, nullptr);
  EXPECT_NEAR(glm::length(*projection->forward({0.0, 0.0})), kMars.semiMajorAxis, 1e-6);
}

TEST(ProjectionTypes, PeriodsAreOneTurnOfTheMap) {
  for (const ProjectionCase& projectionCase : projectionCases()) {
    const auto projection = makeProjection(projectionCase);
    const auto period = projection->periodX();
    const bool periodic = projection->type() == "equirectangular" || projection->type() == "healpix";
    ASSERT_EQ(period.has_value(), periodic) << projectionCase.name;
    if (!period) continue;
    // Along the equator x grows in proportion to longitude: PROJ's x a whisker short of a turn apart.
    const ProjReference proj(referenceDefinition(projectionCase));
    const double centre = projectionCase.centre.x * kPi / 180.0, margin = 1e-6;
    const double span = proj.forward({centre + kPi - margin, 0.0})->x - proj.forward({centre - kPi + margin, 0.0})->x;
    EXPECT_NEAR(span * kPi / (kPi - margin), *period, 1e-6 * *period / kTexelsAcross) << projectionCase.name;
  }
}

TEST(ProjectionTypes, ForwardIsEmptyOffTheBody) {
  for (const ProjectionCase& projectionCase : projectionCases()) {
    const auto projection = makeProjection(projectionCase);
    EXPECT_FALSE(projection->forward({0.1, 1.6})) << projectionCase.name;
    EXPECT_FALSE(projection->forward({std::nan(""), 0.1})) << projectionCase.name;
  }
}

TEST(ProjectionTypes, LongitudesATurnApartMapAlike) {
  for (const ProjectionCase& projectionCase : projectionCases()) {
    const auto projection = makeProjection(projectionCase);
    // A little off the centre, towards the equator: visible from the lowest camera.
    const double towardsEquator = projectionCase.centre.y > 0.0 ? -0.01 : 0.01;
    const glm::dvec2 lonlat = glm::radians(projectionCase.centre) + glm::dvec2(0.01, towardsEquator);
    const auto here = projection->forward(lonlat);
    ASSERT_TRUE(here) << projectionCase.name;
    for (double turns : {-2.0, 1.0, 3.0}) {
      const auto there = projection->forward(lonlat + glm::dvec2(2.0 * kPi * turns, 0.0));
      ASSERT_TRUE(there) << projectionCase.name;
      EXPECT_LE(glm::length(*there - *here), 1e-9 * glm::length(*here) + 1e-9) << projectionCase.name;
    }
  }
}

TEST(ProjectionTypes, GlslFunctionsAreInTheShaderLibrary) {
  const ShaderLibrary library;
  for (const ProjectionCase& projectionCase : projectionCases()) {
    const auto projection = makeProjection(projectionCase);
    ASSERT_TRUE(library.has(projection->glslInclude())) << projection->glslInclude();
    const std::string signature = "vec3 " + projection->glslFunction() + "(vec2 lonlat, vec4 a, vec4 b)";
    EXPECT_NE(library.source(projection->glslInclude()).find(signature), std::string::npos) << signature;
    EXPECT_GT(projection->glslMapScale(), 0.0);
  }
}

}  // namespace
}  // namespace strata::test
