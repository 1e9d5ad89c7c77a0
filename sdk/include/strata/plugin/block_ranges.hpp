#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <utility>
#include <vector>

#include <strata/plugin/layer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The raw values of a raster's square blocks of level-0 texels: what lets a layer bound its heights over a
// region (RegionalValueLayer::valuesWithin), so that a patch of a plateau knows it lies on the plateau
// (docs/geometry.md, "Height ranges"). A source counts them while reading a small raster whole, or reads those `strata
// tile` stored in the file (metadataItems), for a raster of any size.
class BlockRanges {
 public:
  // 8 texels a side at least: a global 15' geoid (1440 x 721) is bounded every 2 degrees, where blocks of 64
  // bounded it every 16 and each patch inside one took the whole block's relief, as if on rough ground
  // (docs/geometry.md, "Level of detail by screen-space error").
  static constexpr int kLeastBlockTexels = 8;
  // At most 65,536 blocks (1.5 MiB here, 768 KiB in a file, 1 MiB of its metadata text): a 4096 x 4096 raster
  // keeps blocks of 16 texels, a 46080 x 23040 global DEM (MOLA's 463 m) blocks of 128, 59 km; blocks are
  // doubled until they fit.
  static constexpr std::size_t kMostBlocks = 65536;
  struct Block {
    double least = std::numeric_limits<double>::infinity();
    double greatest = -std::numeric_limits<double>::infinity();
    std::int64_t counted = 0;  // texels that hold data
    // The largest second differences of the block's texels (countBends), raw: along a row, along a column, and
    // their twist (the mixed difference); < 0: none counted, the bends unknown.
    double rowBend = -1.0, columnBend = -1.0, twist = -1.0;
    bool bendsCounted() const { return rowBend >= 0.0; }
  };

  // Blocks of `blockTexels` a side (a power of two, at least kLeastBlockTexels).
  BlockRanges(int width, int height, int blockTexels);
  // The least block side from kLeastBlockTexels up that makes at most kMostBlocks blocks of a width x height
  // raster: counted as a source opens it and stored by `strata tile` alike.
  static int blockTexelsFor(int width, int height);

  // A texel that holds data (drawn: finite and let through by the mask).
  void count(int column, int row, double value);
  // The bends of row `row`'s texels from it and the rows above and below (each width() values, NaN where no
  // data is drawn): a texel's second differences along the row and the column and their twist, the values'
  // second derivatives there in raw units per texel squared. Only texels whose eight neighbours all hold data
  // are counted: a block's bends are unknown where none of its texels is.
  void countBends(int row, const std::vector<double>& above, const std::vector<double>& here,
                  const std::vector<double>& below);
  // Every block's bend unknown again: for a raster some of whose rows could not be read for them.
  void forgetBends();

  int width() const { return width_; }
  int height() const { return height_; }
  int blockTexels() const { return blockTexels_; }
  int columns() const { return columns_; }  // blocks across
  int rows() const { return rows_; }        // blocks down
  const Block& at(int blockColumn, int blockRow) const { return blocks_[index(blockColumn, blockRow)]; }
  // Whether some texel of the block holds no data (nodata, masked, unreadable): the sphere shows there.
  bool holdsGaps(int blockColumn, int blockRow) const;
  // The extremes of every counted texel; none where no texel holds data.
  std::optional<ValueRange> whole() const;

  // Blocks twice as large each way, each holding the four it covers (their bends unknown: files store none).
  BlockRanges coarsened() const;

  // The items that store the ranges in a file's metadata (GDAL's default domain), coarsened to at most
  // kMostBlocks; extremes as floats rounded outwards, so that they still bound every value. And the
  // ranges read back from them (`item` gives an item's value, or null): none where the file has none or
  // they do not fit a raster of width x height.
  std::vector<std::pair<std::string, std::string>> metadataItems() const;
  using MetadataItem = std::function<const char*(const std::string& name)>;
  static std::optional<BlockRanges> fromMetadata(int width, int height, const MetadataItem& item);
  // Whether the metadata holds such items at all, read back or not.
  static bool inMetadata(const MetadataItem& item);

 private:
  std::size_t index(int blockColumn, int blockRow) const { return std::size_t(blockRow) * columns_ + blockColumn; }
  std::int64_t texelsOf(int blockColumn, int blockRow) const;

  int width_, height_, blockTexels_, columns_, rows_;
  std::vector<Block> blocks_;
};

}  // namespace strata
STRATA_EXPORTS_END
