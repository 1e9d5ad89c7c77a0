#include <gtest/gtest.h>

#include <strata/error.hpp>

namespace strata {
namespace {

TEST(SourceLocationTest, NamesFileLineAndColumn) {
  EXPECT_EQ((SourceLocation{"demo.yaml", 12, 7, {}}).str(), "demo.yaml:12:7");
}

TEST(SourceLocationTest, NamesOnlyTheFileWithoutALine) {
  EXPECT_EQ((SourceLocation{"--set", 0, 0, {}}).str(), "--set");
}

TEST(SourceLocationTest, AppendsTheNode) {
  EXPECT_EQ((SourceLocation{"demo.yaml", 3, 5, "relief"}).str(), "demo.yaml:3:5 (node 'relief')");
  EXPECT_EQ((SourceLocation{"--set", 0, 0, "relief"}).str(), "--set (node 'relief')");
}

TEST(ErrorTest, WhatJoinsLocationProblemAndFix) {
  const Error error(SourceLocation{"demo.yaml", 4, 9, "frame"}, "unknown key 'sufrace'", "write 'surface'");
  EXPECT_STREQ(error.what(), "demo.yaml:4:9 (node 'frame'): error: unknown key 'sufrace'\n  fix: write 'surface'");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 9);
  EXPECT_EQ(error.where().node, "frame");
  EXPECT_EQ(error.problem(), "unknown key 'sufrace'");
  EXPECT_EQ(error.fix(), "write 'surface'");
}

TEST(ErrorTest, WhatHasNoFixLineWithoutAFix) {
  const Error error(SourceLocation{"demo.yaml", 0, 0, {}}, "pipeline file not found");
  EXPECT_STREQ(error.what(), "demo.yaml: error: pipeline file not found");
  EXPECT_TRUE(error.fix().empty());
}

TEST(ErrorTest, IsARuntimeError) {
  try {
    throw Error(SourceLocation{"a.yaml", 1, 1, {}}, "problem", "fix");
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("a.yaml:1:1: error: problem"), std::string::npos);
  }
}

}  // namespace
}  // namespace strata
