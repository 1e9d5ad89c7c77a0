// `grid: 512x512` as a pipeline writes it: two whole numbers within [kLeastGridSide, kGreatestGridSide]
// joined by an x, and nothing else.
#include <gtest/gtest.h>

#include "grid_size.hpp"

namespace strata::pgm {
namespace {

TEST(PgmGridSize, ColumnsByRows) {
  EXPECT_EQ(parseGridSize("512x512"), glm::ivec2(512, 512));
  EXPECT_EQ(parseGridSize("256x1024"), glm::ivec2(256, 1024));
  EXPECT_EQ(parseGridSize("2x4096"), glm::ivec2(2, 4096));
}

TEST(PgmGridSize, AnythingElseIsNoGrid) {
  for (const char* text : {"", "512", "512x", "x512", "512X512", "512 x 512", "512x512x2", "-4x4", "1x512", "512x4097",
                           "0x0", "512.5x512", "99999999999x2"})
    EXPECT_EQ(parseGridSize(text), std::nullopt) << text;
}

}  // namespace
}  // namespace strata::pgm
