// geometry.bdam's diamonds, the builder's unit of work: at every level each node lies in exactly one, its two halves
// share their hypotenuse (on a face, or across one of the cube's edges at odd levels), and its children meet at that
// hypotenuse's midpoint.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "diamonds.hpp"
#include "displaced_triangle.hpp"

namespace strata::bdam {
namespace {

TEST(Diamonds, EveryNodeOfALevelLiesInExactlyOneAndItsHalvesShareTheirHypotenuse) {
  for (int level = 0; level <= 9; ++level) {
    std::set<std::tuple<int, std::uint64_t>> seen;
    int acrossFaces = 0;
    const std::vector<Diamond> diamonds = diamondsOf(level);
    ASSERT_EQ(diamonds.size(), std::size_t(6) << level);
    for (const Diamond& diamond : diamonds) {
      for (const BintreeNode& half : diamond.halves) {
        ASSERT_EQ(half.level, level);
        ASSERT_TRUE(seen.insert({half.root, half.path}).second) << "a node in two diamonds";
      }
      const DisplacedTriangle a = displacedTriangle(diamond.halves[0], 1.0),
                              b = displacedTriangle(diamond.halves[1], 1.0);
      ASSERT_EQ(a.corners[1], b.corners[2]);  // the partner walks the hypotenuse the other way
      ASSERT_EQ(a.corners[2], b.corners[1]);
      for (const BintreeNode& child : diamond.children())
        ASSERT_EQ(displacedTriangle(child, 1.0).corners[0], displacedTriangle(diamond.children()[0], 1.0).corners[0]);
      acrossFaces += faceOf(diamond.halves[0]) != faceOf(diamond.halves[1]);
    }
    // Hypotenuses run along the cube's edges at odd levels only: its 12 edges, in 2^((level - 1) / 2) pieces each.
    EXPECT_EQ(acrossFaces, level % 2 ? 12 << (level - 1) / 2 : 0) << "level " << level;
  }
}

}  // namespace
}  // namespace strata::bdam
