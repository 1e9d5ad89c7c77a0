#include <gtest/gtest.h>

#include "pipeline/graph_order.hpp"

namespace strata::loader {
namespace {

using Order = std::vector<std::size_t>;

TEST(GraphOrderTest, KeepsAFileAlreadyInDependencyOrder) {
  // 0 <- 1 <- 2, 3 independent
  const DependencyOrder result = orderByDependencies({{}, {0}, {1}, {}});
  EXPECT_EQ(result.order, (Order{0, 1, 2, 3}));
  EXPECT_TRUE(result.cycle.empty());
}

TEST(GraphOrderTest, PutsInputsBeforeTheirUsers) {
  // frame(0) <- terrain(1), imagery(3); terrain(1) <- relief(2)
  const DependencyOrder result = orderByDependencies({{1, 3}, {2}, {}, {}});
  EXPECT_EQ(result.order, (Order{2, 1, 3, 0}));
  EXPECT_TRUE(result.cycle.empty());
}

TEST(GraphOrderTest, AmongReadyNodesTheEarliestInTheFileGoesFirst) {
  // 0 needs 3; 1 and 2 need nothing; 3 needs 2. Ready at first: 1, 2. Then 3 becomes ready, then 0.
  const DependencyOrder result = orderByDependencies({{3}, {}, {}, {2}});
  EXPECT_EQ(result.order, (Order{1, 2, 3, 0}));
}

TEST(GraphOrderTest, RepeatedInputsAreWaitedForTogether) {
  const DependencyOrder result = orderByDependencies({{1, 1}, {}});
  EXPECT_EQ(result.order, (Order{1, 0}));
  EXPECT_TRUE(result.cycle.empty());
}

TEST(GraphOrderTest, EmptyGraph) {
  const DependencyOrder result = orderByDependencies({});
  EXPECT_TRUE(result.order.empty());
  EXPECT_TRUE(result.cycle.empty());
}

TEST(GraphOrderTest, FindsACycleStartingAtItsEarliestNode) {
  // 0 free; 1 <- 3 <- 2 <- 1; 4 depends on the cycle
  const DependencyOrder result = orderByDependencies({{}, {3}, {1}, {2}, {1}});
  EXPECT_EQ(result.cycle, (Order{1, 3, 2}));
  EXPECT_EQ(result.order, (Order{0}));
}

TEST(GraphOrderTest, CycleReachedThroughATail) {
  // 0 takes input from 1, which is in the cycle 1 <-> 2: 0 is not part of the cycle.
  const DependencyOrder result = orderByDependencies({{1}, {2}, {1}});
  EXPECT_EQ(result.cycle, (Order{1, 2}));
  EXPECT_TRUE(result.order.empty());
}

TEST(GraphOrderTest, SelfLoopIsACycleOfOne) {
  const DependencyOrder result = orderByDependencies({{}, {1}});
  EXPECT_EQ(result.cycle, (Order{1}));
  EXPECT_EQ(result.order, (Order{0}));
}

}  // namespace
}  // namespace strata::loader
