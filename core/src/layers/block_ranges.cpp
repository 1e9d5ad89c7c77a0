#include <strata/block_ranges.hpp>

#include <algorithm>

namespace strata {

BlockRanges::BlockRanges(int width, int height)
    : width_(width),
      height_(height),
      columns_((width + kBlockTexels - 1) / kBlockTexels),
      rows_((height + kBlockTexels - 1) / kBlockTexels),
      blocks_(std::size_t(columns_) * std::size_t(rows_)) {}

void BlockRanges::count(int column, int row, double value) {
  Block& block = blocks_[index(column / kBlockTexels, row / kBlockTexels)];
  block.least = std::min(block.least, value);
  block.greatest = std::max(block.greatest, value);
  ++block.counted;
}

bool BlockRanges::holdsGaps(int blockColumn, int blockRow) const {
  const int across = std::min(kBlockTexels, width_ - blockColumn * kBlockTexels);
  const int down = std::min(kBlockTexels, height_ - blockRow * kBlockTexels);
  return at(blockColumn, blockRow).counted < across * down;
}

std::optional<ValueRange> BlockRanges::whole() const {
  std::optional<ValueRange> range;
  for (const Block& block : blocks_) {
    if (block.counted == 0) continue;
    range = range ? ValueRange{std::min(range->least, block.least), std::max(range->greatest, block.greatest)}
                  : ValueRange{block.least, block.greatest};
  }
  return range;
}

}  // namespace strata
