#include <gtest/gtest.h>

#include "pipeline/suggestions.hpp"

namespace strata::loader {
namespace {

TEST(EditDistanceTest, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("camera", "camera"), 0u);
  EXPECT_EQ(editDistance("camara", "camera"), 1u);
  EXPECT_EQ(editDistance("relif", "relief"), 1u);
  EXPECT_EQ(editDistance("reliefs", "relief"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(EditDistanceTest, SwappedNeighboursAreOneEdit) {
  EXPECT_EQ(editDistance("scael", "scale"), 1u);
  EXPECT_EQ(editDistance("sruface", "surface"), 1u);
}

TEST(EditDistanceTest, IgnoresCase) { EXPECT_EQ(editDistance("Camera", "camera"), 0u); }

TEST(ClosestMatchTest, FindsTheNearestCandidate) {
  const std::vector<std::string> keys{"strata", "body", "camera", "nodes"};
  EXPECT_EQ(closestMatch("camara", keys), "camera");
  EXPECT_EQ(closestMatch("node", keys), "nodes");
  EXPECT_EQ(closestMatch("Strata", keys), "strata");
}

TEST(ClosestMatchTest, SuggestsNothingFarAway) {
  const std::vector<std::string> keys{"strata", "body", "camera", "nodes"};
  EXPECT_EQ(closestMatch("lighting", keys), std::nullopt);
  EXPECT_EQ(closestMatch("x", keys), std::nullopt);
  EXPECT_EQ(closestMatch("camera", {}), std::nullopt);
}

TEST(ClosestMatchTest, ToleranceGrowsWithTheWord) {
  // One edit per three letters: two edits are fine in six letters, not in five.
  EXPECT_EQ(closestMatch("cmaera", {"camera"}), "camera");  // a swap: one edit
  EXPECT_EQ(closestMatch("camxrz", {"camera"}), "camera");  // two substitutions
  EXPECT_EQ(closestMatch("cxmxr", {"camer"}), std::nullopt);
}

TEST(ClosestMatchTest, TiesGoToTheEarlierCandidate) {
  EXPECT_EQ(closestMatch("lan", {"lon", "lat"}), "lon");
  EXPECT_EQ(closestMatch("lan", {"lat", "lon"}), "lat");
}

TEST(DidYouMeanTest, FormatsASuggestionOrNothing) {
  EXPECT_EQ(didYouMean("camara", {"camera"}), "; did you mean 'camera'?");
  EXPECT_EQ(didYouMean("lighting", {"camera"}), "");
}

TEST(QuotedListTest, QuotesAndSeparatesNames) {
  EXPECT_EQ(quotedList({"a", "b", "c"}), "'a', 'b', 'c'");
  EXPECT_EQ(quotedList({"only"}), "'only'");
  EXPECT_EQ(quotedList({}), "");
}

}  // namespace
}  // namespace strata::loader
