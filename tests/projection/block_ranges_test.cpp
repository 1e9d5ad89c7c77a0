// A raster's block ranges stored in a file's metadata (strata/plugin/block_ranges.hpp) and read back: every value a
// block holds stays within its stored range although floats hold the extremes, blocks with gaps keep them,
// a raster too large for the file's share is stored in larger blocks, and items that do not fit the raster
// or are damaged are refused rather than trusted. And the texels' bends, which files do not store.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <strata/plugin/block_ranges.hpp>

namespace strata {
namespace {

using Items = std::map<std::string, std::string>;

BlockRanges::MetadataItem lookup(const Items& items) {
  return [&items](const std::string& name) {
    const auto found = items.find(name);
    return found == items.end() ? nullptr : found->second.c_str();
  };
}

Items stored(const BlockRanges& ranges) {
  Items items;
  for (const auto& [name, value] : ranges.metadataItems()) items[name] = value;
  return items;
}

// Values no float holds exactly (a tenth of odd numbers), and no data in the texels of every seventh column.
double valueAt(int column, int row) {
  return 0.1 * double(2 * ((std::int64_t{column} * 7919 + std::int64_t{row} * 104729) % 5001) + 1) - 500.0;
}
bool holdsData(int column) { return column % 7 != 0 || column > 250; }

TEST(BlockRanges, StoredRangesHoldEveryValueOfTheirBlocks) {
  constexpr int kWidth = 300, kHeight = 200;
  BlockRanges counted(kWidth, kHeight, 64);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column)
      if (holdsData(column)) counted.count(column, row, valueAt(column, row));
  const Items items = stored(counted);
  const std::optional<BlockRanges> read = BlockRanges::fromMetadata(kWidth, kHeight, lookup(items));
  ASSERT_TRUE(read);
  EXPECT_EQ(read->blockTexels(), 64);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      if (!holdsData(column)) continue;
      const BlockRanges::Block& block = read->at(column / 64, row / 64);
      ASSERT_LE(block.least, valueAt(column, row)) << column << ", " << row;
      ASSERT_GE(block.greatest, valueAt(column, row)) << column << ", " << row;
    }
  for (int row = 0; row < read->rows(); ++row)
    for (int column = 0; column < read->columns(); ++column) {
      EXPECT_EQ(read->holdsGaps(column, row), counted.holdsGaps(column, row)) << column << ", " << row;
      EXPECT_EQ(read->at(column, row).counted, counted.at(column, row).counted);
      EXPECT_NEAR(read->at(column, row).least, counted.at(column, row).least, 1e-4) << "rounded outwards, no more";
    }
  EXPECT_TRUE(read->holdsGaps(0, 0));
  EXPECT_FALSE(read->holdsGaps(4, 3)) << "columns 256 to 299 all hold data";
}

// 40000 x 20000 texels in blocks of 64 are 195,625 blocks: stored in blocks of 128, 48,907 of them. A small
// raster keeps small blocks: a 15' global geoid blocks of 8 texels, 2 degrees.
TEST(BlockRanges, ALargeRasterIsStoredInLargerBlocks) {
  constexpr int kWidth = 40000, kHeight = 20000;
  EXPECT_EQ(BlockRanges::blockTexelsFor(kWidth, kHeight), 128);
  EXPECT_EQ(BlockRanges::blockTexelsFor(4096, 4096), 16);
  EXPECT_EQ(BlockRanges::blockTexelsFor(46080, 23040), 128);
  EXPECT_EQ(BlockRanges::blockTexelsFor(1440, 721), 8);
  BlockRanges counted(kWidth, kHeight, 64);
  std::mt19937 random(3);
  std::uniform_int_distribution<int> column(0, kWidth - 1), row(0, kHeight - 1);
  std::vector<std::array<int, 2>> texels;
  for (int i = 0; i < 20000; ++i) {
    texels.push_back({column(random), row(random)});
    counted.count(texels.back()[0], texels.back()[1], valueAt(texels.back()[0], texels.back()[1]));
  }
  const Items items = stored(counted);
  const std::optional<BlockRanges> read = BlockRanges::fromMetadata(kWidth, kHeight, lookup(items));
  ASSERT_TRUE(read);
  EXPECT_EQ(read->blockTexels(), 128);
  EXPECT_LE(std::size_t(read->columns()) * std::size_t(read->rows()), BlockRanges::kMostBlocks);
  for (const auto& [x, y] : texels) {
    const BlockRanges::Block& block = read->at(x / 128, y / 128);
    ASSERT_LE(block.least, valueAt(x, y));
    ASSERT_GE(block.greatest, valueAt(x, y));
  }
  EXPECT_TRUE(read->holdsGaps(0, 0)) << "a few texels a block";
  EXPECT_LE(read->whole()->least, counted.whole()->least);
  EXPECT_NEAR(read->whole()->least, counted.whole()->least, 1e-4);
}

// A texel's bends (BlockRanges::countBends) are its second differences: on the quadric 0.5 a x^2 + 0.5 b y^2 + c x y
// (texels) exactly a along rows, b along columns and c of twist, whatever the offsets; a texel beside no data
// counts none, so a block all of whose texels are is unknown, as are all blocks after forgetBends() and blocks
// read from a file, which stores none.
TEST(BlockRanges, BendsAreTheTexelsSecondDifferences) {
  constexpr int kWidth = 24, kHeight = 16;
  constexpr double a = 0.75, b = -2.5, c = 0.375;  // binary fractions: the differences are exact
  const auto value = [](int x, int y) {
    return x < 16 ? 0.5 * a * x * x + 0.5 * b * y * y + c * x * y + 3.0 * x - 7.0 * y + 100.0
                  : std::numeric_limits<double>::quiet_NaN();
  };
  BlockRanges blocks(kWidth, kHeight, 8);
  std::vector<std::vector<double>> rows;
  for (int y = 0; y < kHeight; ++y) {
    rows.emplace_back();
    for (int x = 0; x < kWidth; ++x) rows.back().push_back(value(x, y));
  }
  for (int y = 1; y + 1 < kHeight; ++y)
    blocks.countBends(y, rows[std::size_t(y - 1)], rows[std::size_t(y)], rows[std::size_t(y + 1)]);
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 2; ++column) {
      const BlockRanges::Block& block = blocks.at(column, row);
      ASSERT_TRUE(block.bendsCounted());
      EXPECT_EQ(block.rowBend, a);
      EXPECT_EQ(block.columnBend, -b);
      EXPECT_EQ(block.twist, c);
    }
  EXPECT_FALSE(blocks.at(2, 0).bendsCounted()) << "every texel there holds no data, or lies beside some";
  EXPECT_FALSE(BlockRanges::fromMetadata(kWidth, kHeight, lookup(stored(blocks)))->at(0, 0).bendsCounted());
  blocks.forgetBends();
  EXPECT_FALSE(blocks.at(0, 0).bendsCounted());
}

TEST(BlockRanges, ItemsThatDoNotFitTheRasterOrAreDamagedAreRefused) {
  BlockRanges counted(300, 200, 64);
  counted.count(10, 10, 5.0);
  Items items = stored(counted);
  EXPECT_TRUE(BlockRanges::fromMetadata(300, 200, lookup(items)));
  EXPECT_TRUE(BlockRanges::inMetadata(lookup(items)));
  EXPECT_FALSE(BlockRanges::fromMetadata(400, 200, lookup(items))) << "another raster's blocks";
  EXPECT_TRUE(BlockRanges::fromMetadata(310, 200, lookup(items))) << "the same 5 x 4 blocks: nothing tells it";
  for (const std::string texels : {"96", "4", "64x", "-64", ""}) {
    Items wrong = items;
    wrong["STRATA_BLOCK_TEXELS"] = texels;
    EXPECT_FALSE(BlockRanges::fromMetadata(300, 200, lookup(wrong))) << "blocks of '" << texels << "'";
  }
  Items cut = items;
  cut["STRATA_BLOCK_RANGES"].resize(cut["STRATA_BLOCK_RANGES"].size() / 2);
  EXPECT_FALSE(BlockRanges::fromMetadata(300, 200, lookup(cut)));
  Items none;
  EXPECT_FALSE(BlockRanges::fromMetadata(300, 200, lookup(none)));
  EXPECT_FALSE(BlockRanges::inMetadata(lookup(none)));
}

}  // namespace
}  // namespace strata
