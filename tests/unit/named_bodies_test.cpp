// The bodies a pipeline may name, against the IAU report's radii [Archinal 2018].
#include <gtest/gtest.h>

#include <strata/named_bodies.hpp>

namespace strata {
namespace {

// Mean radii (km) as [Archinal 2018] gives them, typed again here from its tables so that a slip in the
// library's table shows; the Earth's is Strata's kilometre-rounded 6371 (the report: 6371.0084).
TEST(NamedBodies, MeanRadiiAreTheIauReports) {
  const std::pair<const char*, double> report[] = {
      {"Sun", 695700.0},   {"Mercury", 2440.53}, {"Venus", 6051.8},   {"Earth", 6371.0},    {"Moon", 1737.4},
      {"Mars", 3389.5},    {"Jupiter", 69911.0}, {"Io", 1821.49},     {"Europa", 1560.8},   {"Ganymede", 2631.2},
      {"Saturn", 58232.0}, {"Titan", 2575.0},    {"Uranus", 25362.0}, {"Neptune", 24622.0}, {"Pluto", 1188.3}};
  for (const auto& [name, km] : report) {
    const NamedBody* body = findNamedBody(name);
    ASSERT_NE(body, nullptr) << name;
    EXPECT_DOUBLE_EQ(body->meanRadius, km * 1000.0) << name;
  }
}

TEST(NamedBodies, NamesAreFoundWhateverTheirCase) {
  EXPECT_EQ(findNamedBody("MARS"), findNamedBody("Mars"));
  EXPECT_EQ(findNamedBody("moon"), findNamedBody("Moon"));
  EXPECT_EQ(findNamedBody("Vulcan"), nullptr);
  EXPECT_EQ(findNamedBody(""), nullptr);
}

TEST(NamedBodies, EveryMeanRadiusLiesBetweenItsEllipsoidsAxes) {
  for (const NamedBody& body : namedBodies()) {
    EXPECT_LE(body.polarRadius, body.meanRadius) << body.name;
    EXPECT_GE(body.equatorialRadius, body.meanRadius) << body.name;
  }
}

// WGS 84's semi-major axis and the Earth's mean radius are the Earth; the Mars 2000 sphere is not.
TEST(NamedBodies, ARadiusFitsTheBodyWhoseEllipsoidHoldsIt) {
  const NamedBody& earth = *findNamedBody("Earth");
  EXPECT_TRUE(radiusFits(earth, 6378137.0));
  EXPECT_TRUE(radiusFits(earth, 6371000.0));
  EXPECT_FALSE(radiusFits(earth, 3396190.0));
  EXPECT_FALSE(radiusFits(earth, 6371.0));
}

}  // namespace
}  // namespace strata
