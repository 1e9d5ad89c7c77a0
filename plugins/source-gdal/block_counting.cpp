#include "block_counting.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "drawn_window.hpp"

namespace strata::gdal {
namespace {

constexpr int kRowsAtATime = 256;  // as value_range.cpp reads: 8 MiB of doubles for a 4096-wide raster

// Rows [first, first + count) of band 1 as doubles, NaN where no data is drawn; false where they cannot be read.
bool readRows(GDALRasterBand& band, int first, int count, std::vector<std::vector<double>>& rows) {
  const std::optional<std::vector<double>> window = readDrawnWindow(band, 0, first, band.GetXSize(), count);
  if (!window) return false;
  for (auto line = window->begin(); line != window->end(); line += band.GetXSize())
    rows.emplace_back(line, line + band.GetXSize());
  return true;
}

// Row `row`'s texels that can be drawn (those not NaN in `line`).
void countRow(BlockRanges& blocks, int row, const std::vector<double>& line) {
  for (std::size_t x = 0; x < line.size(); ++x)
    if (!std::isnan(line[x])) blocks.count(int(x), row, line[x]);
}

}  // namespace

void countBlocks(GDALRasterBand& band, BlockRanges& blocks, const UnreadableRows& unreadable) {
  const int height = band.GetYSize();
  bool bending = true;  // every band so far read whole
  for (int row = 0; row < height; row += kRowsAtATime) {
    const int last = std::min(row + kRowsAtATime, height);
    const int above = std::max(row - 1, 0), below = std::min(last + 1, height);  // read with its neighbours
    std::vector<std::vector<double>> rows;
    if (!readRows(band, above, below - above, rows)) {
      unreadable(row, last - row);
      if (bending) blocks.forgetBends();
      bending = false;
      continue;
    }
    for (int y = row; y < last; ++y) countRow(blocks, y, rows[std::size_t(y - above)]);
    for (int y = std::max(row, 1); bending && y < std::min(last, height - 1); ++y)
      blocks.countBends(y, rows[std::size_t(y - 1 - above)], rows[std::size_t(y - above)],
                        rows[std::size_t(y + 1 - above)]);
  }
}

}  // namespace strata::gdal
