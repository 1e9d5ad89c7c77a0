#include <gtest/gtest.h>

#include <stdexcept>

#include <strata/plugin/parameter.hpp>

namespace strata {
namespace {

const SourceLocation kHere{"demo.yaml", 5, 11, "relief"};

ParameterSet sampleSet() {
  ParameterSet set;
  set.set("skirts", true, kHere);
  set.set("levels", std::int64_t{7}, kHere);
  set.set("scale", 300.0, kHere);
  set.set("kind", std::string("height"), kHere);
  set.set("path", std::string("/data/relief.tif"), kHere);
  set.set("size", std::vector<double>{1920, 1080}, kHere);
  return set;
}

TEST(ParameterSetTest, ReturnsEachTypeItsValue) {
  const ParameterSet set = sampleSet();
  EXPECT_TRUE(set.boolean("skirts"));
  EXPECT_EQ(set.integer("levels"), 7);
  EXPECT_DOUBLE_EQ(set.real("scale"), 300.0);
  EXPECT_EQ(set.string("kind"), "height");
  EXPECT_EQ(set.path("path"), std::filesystem::path("/data/relief.tif"));
  EXPECT_EQ(set.reals("size"), (std::vector<double>{1920, 1080}));
  EXPECT_EQ(std::get<double>(set.value("scale")), 300.0);
}

TEST(ParameterSetTest, HasOnlyWhatWasSet) {
  const ParameterSet set = sampleSet();
  EXPECT_TRUE(set.has("scale"));
  EXPECT_FALSE(set.has("exaggeration"));
}

TEST(ParameterSetTest, SetReplacesValueAndLocation) {
  ParameterSet set = sampleSet();
  set.set("scale", 50.0, SourceLocation{"--set", 0, 0, "relief"});
  EXPECT_DOUBLE_EQ(set.real("scale"), 50.0);
  EXPECT_EQ(set.where("scale").file, "--set");
}

TEST(ParameterSetTest, WhereReturnsTheLocation) {
  const ParameterSet set = sampleSet();
  EXPECT_EQ(set.where("levels").str(), "demo.yaml:5:11 (node 'relief')");
}

TEST(ParameterSetTest, WrongTypeAccessIsALogicErrorNamingTheParameter) {
  const ParameterSet set = sampleSet();
  try {
    set.integer("scale");
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("'scale'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("integer"), std::string::npos) << error.what();
  }
  EXPECT_THROW(set.real("levels"), std::logic_error);
  EXPECT_THROW(set.boolean("kind"), std::logic_error);
  EXPECT_THROW(set.string("scale"), std::logic_error);
  EXPECT_THROW(set.path("levels"), std::logic_error);
  EXPECT_THROW(set.reals("scale"), std::logic_error);
}

TEST(ParameterSetTest, UnknownNameIsALogicErrorNamingIt) {
  const ParameterSet set = sampleSet();
  try {
    set.value("exaggeration");
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("'exaggeration'"), std::string::npos) << error.what();
  }
  EXPECT_THROW(set.where("exaggeration"), std::logic_error);
  EXPECT_THROW(set.real("exaggeration"), std::logic_error);
}

TEST(FormatValueTest, WritesValuesAsAPipelineWould) {
  EXPECT_EQ(formatValue(true), "true");
  EXPECT_EQ(formatValue(false), "false");
  EXPECT_EQ(formatValue(std::int64_t{300}), "300");
  EXPECT_EQ(formatValue(std::int64_t{-4}), "-4");
  EXPECT_EQ(formatValue(300.0), "300");
  EXPECT_EQ(formatValue(0.25), "0.25");
  EXPECT_EQ(formatValue(0.1), "0.1");
  EXPECT_EQ(formatValue(std::string("text")), "text");
  EXPECT_EQ(formatValue(std::vector<double>{1, 2.5, 3}), "[1, 2.5, 3]");
  EXPECT_EQ(formatValue(std::vector<double>{}), "[]");
}

TEST(FormatValueTest, RealsReadBackExactly) {
  for (double value : {6371000.0, 2.0e7, 1.0 / 3.0, -1e-9}) {
    EXPECT_EQ(std::stod(formatValue(value)), value) << formatValue(value);
  }
}

}  // namespace
}  // namespace strata
