#include <strata/plugin/block_ranges.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>

#include "foundation/metadata_words.hpp"

namespace strata {
namespace {

constexpr const char* kTexelsItem = "STRATA_BLOCK_TEXELS";
constexpr const char* kRangesItem = "STRATA_BLOCK_RANGES";
// Blocks of 2^30 texels a side hold any raster GDAL opens in one block.
constexpr int kMostBlockTexels = 1 << 30;

// The float nearest `value` on the side `towards` (-inf: not above it, +inf: not below it).
float roundedOutwards(double value, float towards) {
  float rounded = float(value);
  if ((towards < 0.0f && double(rounded) > value) || (towards > 0.0f && double(rounded) < value))
    rounded = std::nextafter(rounded, towards);
  return rounded;
}

constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

BlockRanges::BlockRanges(int width, int height, int blockTexels)
    : width_(width),
      height_(height),
      blockTexels_(blockTexels),
      columns_(int((std::int64_t(width) + blockTexels - 1) / blockTexels)),
      rows_(int((std::int64_t(height) + blockTexels - 1) / blockTexels)),
      blocks_(std::size_t(columns_) * std::size_t(rows_)) {}

int BlockRanges::blockTexelsFor(int width, int height) {
  int side = kLeastBlockTexels;
  while (((std::int64_t(width) + side - 1) / side) * ((std::int64_t(height) + side - 1) / side) >
         std::int64_t(kMostBlocks))
    side *= 2;
  return side;
}

void BlockRanges::count(int column, int row, double value) {
  Block& block = blocks_[index(column / blockTexels_, row / blockTexels_)];
  block.least = std::min(block.least, value);
  block.greatest = std::max(block.greatest, value);
  ++block.counted;
}

void BlockRanges::countBends(int row, const std::vector<double>& above, const std::vector<double>& here,
                             const std::vector<double>& below) {
  for (int x = 1; x + 1 < width_; ++x) {
    const std::size_t i = std::size_t(x);
    const double alongRow = std::abs(here[i - 1] - 2.0 * here[i] + here[i + 1]);
    const double alongColumn = std::abs(above[i] - 2.0 * here[i] + below[i]);
    const double twist = 0.25 * std::abs(below[i + 1] - below[i - 1] - above[i + 1] + above[i - 1]);
    // a neighbour holds no data: the edge of the data is a cliff to the sphere, which no bend bounds
    if (std::isnan(alongRow) || std::isnan(alongColumn) || std::isnan(twist)) continue;
    Block& block = blocks_[index(x / blockTexels_, row / blockTexels_)];
    block.rowBend = std::max(block.rowBend, alongRow);
    block.columnBend = std::max(block.columnBend, alongColumn);
    block.twist = std::max(block.twist, twist);
  }
}

void BlockRanges::forgetBends() {
  for (Block& block : blocks_) block.rowBend = block.columnBend = block.twist = -1.0;
}

std::int64_t BlockRanges::texelsOf(int blockColumn, int blockRow) const {
  const std::int64_t across = std::min<std::int64_t>(blockTexels_, width_ - std::int64_t(blockColumn) * blockTexels_);
  const std::int64_t down = std::min<std::int64_t>(blockTexels_, height_ - std::int64_t(blockRow) * blockTexels_);
  return across * down;
}

bool BlockRanges::holdsGaps(int blockColumn, int blockRow) const {
  return at(blockColumn, blockRow).counted < texelsOf(blockColumn, blockRow);
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

BlockRanges BlockRanges::coarsened() const {
  BlockRanges coarser(width_, height_, 2 * blockTexels_);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column) {
      const Block& block = at(column, row);
      Block& parent = coarser.blocks_[coarser.index(column / 2, row / 2)];
      parent = {std::min(parent.least, block.least), std::max(parent.greatest, block.greatest),
                parent.counted + block.counted};
    }
  return coarser;
}

// Per block three words: the least and greatest value as floats, and the texels holding no data (at most
// 2^32 - 1, which still tells a block with gaps from one without).
std::vector<std::pair<std::string, std::string>> BlockRanges::metadataItems() const {
  if (blocks_.size() > kMostBlocks) return coarsened().metadataItems();
  std::vector<std::uint32_t> words;
  words.reserve(blocks_.size() * 3);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column) {
      const Block& block = at(column, row);
      const std::int64_t missing = texelsOf(column, row) - block.counted;
      words.push_back(std::bit_cast<std::uint32_t>(roundedOutwards(block.least, -kInfinity)));
      words.push_back(std::bit_cast<std::uint32_t>(roundedOutwards(block.greatest, kInfinity)));
      words.push_back(std::uint32_t(std::min<std::int64_t>(missing, 0xffffffff)));
    }
  return {{kTexelsItem, std::to_string(blockTexels_)}, {kRangesItem, base64OfWords(words)}};
}

bool BlockRanges::inMetadata(const MetadataItem& item) { return item(kTexelsItem) || item(kRangesItem); }

std::optional<BlockRanges> BlockRanges::fromMetadata(int width, int height, const MetadataItem& item) {
  const char* texels = item(kTexelsItem);
  const char* text = item(kRangesItem);
  if (!texels || !text) return std::nullopt;
  char* end = nullptr;
  const long blockTexels = std::strtol(texels, &end, 10);
  if (*end != '\0' || blockTexels < kLeastBlockTexels || blockTexels > kMostBlockTexels ||
      !std::has_single_bit(std::uint64_t(blockTexels)))
    return std::nullopt;
  BlockRanges ranges(width, height, int(blockTexels));
  const std::optional<std::vector<std::uint32_t>> words = wordsOfBase64(text, ranges.blocks_.size() * 3);
  if (!words) return std::nullopt;
  for (int row = 0; row < ranges.rows_; ++row)
    for (int column = 0; column < ranges.columns_; ++column) {
      const std::size_t i = ranges.index(column, row);
      const double least = std::bit_cast<float>((*words)[3 * i]), greatest = std::bit_cast<float>((*words)[3 * i + 1]);
      if (std::isnan(least) || std::isnan(greatest)) return std::nullopt;
      if (least > greatest) continue;  // no data: as constructed
      const std::int64_t counted = ranges.texelsOf(column, row) - std::int64_t((*words)[3 * i + 2]);
      ranges.blocks_[i] = {least, greatest, std::max<std::int64_t>(counted, 1)};
    }
  return ranges;
}

}  // namespace strata
