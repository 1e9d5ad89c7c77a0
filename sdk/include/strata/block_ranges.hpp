#pragma once
#include <strata/export.hpp>
#include <limits>
#include <optional>
#include <vector>

#include <strata/layer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The raw values of a raster's square blocks of level-0 texels, as its source counts them while reading the
// raster whole: what lets a layer bound its heights over a region (Layer::valuesWithin), so that a patch of
// a plateau knows it lies on the plateau (docs/geometry.md, "Height ranges").
class BlockRanges {
 public:
  // 64 texels a side: 4,096 blocks for a 4096 x 4096 raster, each a few vertex spacings of the finest patch
  // that covers it, so that the ranges are about as tight as any patch can use.
  static constexpr int kBlockTexels = 64;

  struct Block {
    double least = std::numeric_limits<double>::infinity();
    double greatest = -std::numeric_limits<double>::infinity();
    int counted = 0;  // texels that hold data
  };

  BlockRanges(int width, int height);

  // A texel that holds data (drawn: finite and let through by the mask).
  void count(int column, int row, double value);

  int width() const { return width_; }
  int height() const { return height_; }
  int columns() const { return columns_; }  // blocks across
  int rows() const { return rows_; }        // blocks down
  const Block& at(int blockColumn, int blockRow) const { return blocks_[index(blockColumn, blockRow)]; }
  // Whether some texel of the block holds no data (nodata, masked, unreadable): the sphere shows there.
  bool holdsGaps(int blockColumn, int blockRow) const;
  // The extremes of every counted texel; none where no texel holds data.
  std::optional<ValueRange> whole() const;

 private:
  std::size_t index(int blockColumn, int blockRow) const { return std::size_t(blockRow) * columns_ + blockColumn; }

  int width_, height_, columns_, rows_;
  std::vector<Block> blocks_;
};

}  // namespace strata
STRATA_EXPORTS_END
