// The page pyramid's arithmetic (strata/plugin/page_pyramid.hpp): levels, their sizes and page counts.
#include <gtest/gtest.h>

#include <strata/plugin/page_pyramid.hpp>

namespace strata {
namespace {

TEST(PagePyramid, EachLevelHalvesTheOneBelowRoundingUpUntilOnePageHoldsIt) {
  const PagePyramid pyramid(40000, 20000);
  ASSERT_EQ(pyramid.levels(), 8);  // 40000 / 2^7 = 312.5: the first level within 512
  EXPECT_EQ(pyramid.levelWidth(0), 40000);
  EXPECT_EQ(pyramid.levelWidth(1), 20000);
  EXPECT_EQ(pyramid.levelWidth(7), 313);
  EXPECT_EQ(pyramid.levelHeight(7), 157);
  EXPECT_EQ(pyramid.pagesAcross(0), 79);  // 78 whole pages and one of 64 texels
  EXPECT_EQ(pyramid.pagesDown(0), 40);
  EXPECT_EQ(pyramid.pageCount(7), 1u);
}

TEST(PagePyramid, ARasterWithinOnePageHasOneLevel) {
  const PagePyramid pyramid(512, 300);
  EXPECT_EQ(pyramid.levels(), 1);
  EXPECT_EQ(pyramid.pageCount(0), 1u);
  EXPECT_EQ(PagePyramid(513, 1).levels(), 2);
}

TEST(PagePyramid, ContainsOnlyPagesOfItsLevels) {
  const PagePyramid pyramid(1500, 700);  // level 0: 3 x 2 pages, level 1: 2 x 1, level 2: 1 x 1
  EXPECT_TRUE(pyramid.contains({0, 2, 1}));
  EXPECT_FALSE(pyramid.contains({0, 3, 0}));
  EXPECT_TRUE(pyramid.contains({1, 1, 0}));
  EXPECT_FALSE(pyramid.contains({1, 0, 1}));
  EXPECT_FALSE(pyramid.contains({3, 0, 0}));
  EXPECT_FALSE(pyramid.contains({0, -1, 0}));
}

}  // namespace
}  // namespace strata
