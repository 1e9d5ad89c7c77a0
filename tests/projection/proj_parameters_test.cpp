// ProjParameters: a PROJ string read as +key[=value] terms, numbers read from them, and the errors a user
// sees for text that is neither.
#include <gtest/gtest.h>

#include <strata/error.hpp>
#include <strata/plugin/projection.hpp>

namespace strata::test {
namespace {

TEST(ProjParameters, ReadsTermsAndFlags) {
  const ProjParameters terms = ProjParameters::parse("+proj=stere +lat_0=-90  +lat_ts=-71\t+R=3396190 +south +no_defs");
  EXPECT_EQ(terms.name(), "stere");
  EXPECT_EQ(terms.real("lat_0", 0.0), -90.0);
  EXPECT_EQ(terms.real("lat_ts", 0.0), -71.0);
  EXPECT_EQ(terms.real("R", 0.0), 3396190.0);
  EXPECT_TRUE(terms.has("south"));
  EXPECT_EQ(terms.terms().at("no_defs"), "");
  EXPECT_FALSE(terms.has("lon_0"));
  EXPECT_EQ(terms.real("lon_0", 12.5), 12.5);
}

TEST(ProjParameters, ReadsNumbersAsProjWritesThem) {
  const ProjParameters terms = ProjParameters::parse("+proj=ups +lat_0=+90 +x_0=2e6 +k=.994 +lon_0=-0.5");
  EXPECT_EQ(terms.real("lat_0", 0.0), 90.0);
  EXPECT_EQ(terms.real("x_0", 0.0), 2e6);
  EXPECT_EQ(terms.real("k", 0.0), 0.994);
  EXPECT_EQ(terms.real("lon_0", 0.0), -0.5);
}

TEST(ProjParameters, TheFirstOfRepeatedTermsCountsAsInProj) {
  EXPECT_EQ(ProjParameters::parse("+proj=eqc +lat_ts=10 +lat_ts=20").real("lat_ts", 0.0), 10.0);
}

TEST(ProjParameters, WithoutProjTheNameIsEmpty) {
  EXPECT_EQ(ProjParameters::parse("+R=1737400").name(), "");
  EXPECT_TRUE(ProjParameters::parse("  ").terms().empty());
}

TEST(ProjParameters, RejectsWhatIsNotATerm) {
  for (const std::string text : {"proj=stere", "+proj=stere lat_0=90", "+", "+=5", "+proj=eqc =3"}) {
    try {
      ProjParameters::parse(text);
      ADD_FAILURE() << "no error for '" << text << "'";
    } catch (const Error& error) {
      EXPECT_NE(error.problem().find(text), std::string::npos) << error.what();
      EXPECT_FALSE(error.fix().empty());
    }
  }
}

TEST(ProjParameters, RejectsValuesThatAreNotNumbers) {
  const ProjParameters terms = ProjParameters::parse("+lat_0=north +lon_0= +south +x_0=1000m +y_0=nan +k=inf +h=+-5");
  for (const std::string key : {"lat_0", "lon_0", "south", "x_0", "y_0", "k", "h"}) {
    try {
      terms.real(key, 0.0);
      ADD_FAILURE() << "no error for +" << key;
    } catch (const Error& error) {
      EXPECT_NE(error.problem().find("+" + key), std::string::npos) << error.what();
      EXPECT_NE(error.fix().find("+" + key), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace strata::test
