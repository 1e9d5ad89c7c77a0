#include "value_range.hpp"

#include <cpl_string.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "block_counting.hpp"
#include "drawn_window.hpp"
#include "quiet_gdal_errors.hpp"
#include "stored_block_ranges.hpp"

namespace strata::gdal {
namespace {

// 16 million texels: a 4096 x 4096 raster, read whole in well under a second.
constexpr double kCountableTexels = 16.0 * 1024 * 1024;

bool finite(const ValueRange& range) { return std::isfinite(range.least) && std::isfinite(range.greatest); }

// Rows read at a time: a band of a 4096-wide raster is 8 MiB of doubles.
constexpr int kRowsAtATime = 256;

// A texel that can be drawn, at (column, row) of level 0.
using DrawnTexel = std::function<void(int column, int row, double value)>;

// Visits the finite values of the window [column, column + columns) x [row, row + rows) that the mask lets
// through. A window that cannot be read is read again block by block (the file's tiles or strips), so that
// only the blocks that cannot be read are left out.
void visitWindow(GDALRasterBand& band, int column, int row, int columns, int rows, const DrawnTexel& visit) {
  const std::optional<std::vector<double>> values = readDrawnWindow(band, column, row, columns, rows);
  if (!values) {
    int blockColumns = 0, blockRows = 0;
    band.GetBlockSize(&blockColumns, &blockRows);
    if (columns <= blockColumns && rows <= blockRows) return;
    for (int y = row; y < row + rows; y = (y / blockRows + 1) * blockRows)
      for (int x = column; x < column + columns; x = (x / blockColumns + 1) * blockColumns)
        visitWindow(band, x, y, std::min((x / blockColumns + 1) * blockColumns, column + columns) - x,
                    std::min((y / blockRows + 1) * blockRows, row + rows) - y, visit);
    return;
  }
  for (std::size_t i = 0; i < values->size(); ++i)
    if (!std::isnan((*values)[i]))
      visit(column + int(i % std::size_t(columns)), row + int(i / std::size_t(columns)), (*values)[i]);
}

// Every texel of band 1 that can be drawn, band of rows by band of rows.
void visitDrawnTexels(GDALRasterBand& band, const DrawnTexel& visit) {
  for (int row = 0; row < band.GetYSize(); row += kRowsAtATime)
    visitWindow(band, 0, row, band.GetXSize(), std::min(kRowsAtATime, band.GetYSize() - row), visit);
}

// The extremes of the finite values the mask lets through: GDAL's own count takes in infinities, which pages
// mask as they mask NaN (raster_reading.cpp), and gives up on a file of which some part cannot be read. Those
// parts are drawn as no data, the sphere, so they bound nothing either. A raster of which nothing is drawn
// returns no value, which any range bounds: {0, 0}.
ValueRange drawnRange(GDALRasterBand& band) {
  std::optional<ValueRange> range;
  visitDrawnTexels(band, [&](int, int, double value) {
    range =
        range ? ValueRange{std::min(range->least, value), std::max(range->greatest, value)} : ValueRange{value, value};
  });
  return range.value_or(ValueRange{0.0, 0.0});
}

ValueRange countedRange(GDALRasterBand& band) {
  double extremes[2] = {0.0, 0.0};
  if (band.ComputeRasterMinMax(FALSE, extremes) != CE_None) return drawnRange(band);
  const ValueRange range{extremes[0], extremes[1]};
  return finite(range) ? range : drawnRange(band);
}

bool countable(GDALDataset& dataset) {
  return double(dataset.GetRasterXSize()) * dataset.GetRasterYSize() <= kCountableTexels;
}

// The file's own statistics, where they are exact.
std::optional<ValueRange> exactStatistics(GDALRasterBand& band) {
  const char* approximate = band.GetMetadataItem("STATISTICS_APPROXIMATE");
  int hasLeast = 0, hasGreatest = 0;
  const double least = band.GetMinimum(&hasLeast), greatest = band.GetMaximum(&hasGreatest);
  if (hasLeast && hasGreatest && !(approximate && CPLTestBool(approximate)) && finite({least, greatest}))
    return ValueRange{least, greatest};
  return std::nullopt;
}

}  // namespace

std::optional<ValueRange> exactRawRange(GDALDataset& dataset) {
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  if (const std::optional<ValueRange> statistics = exactStatistics(band)) return statistics;
  if (!countable(dataset)) return std::nullopt;
  const QuietGdalErrors quiet;  // a file that cannot be read whole is reported page by page when drawn
  return countedRange(band);
}

std::optional<ValueRange> exactRawRange(GDALDataset& dataset, const BlockRanges& blocks) {
  if (const std::optional<ValueRange> statistics = exactStatistics(*dataset.GetRasterBand(1))) return statistics;
  return blocks.whole().value_or(ValueRange{0.0, 0.0});
}

std::shared_ptr<BlockRanges> blockRangesOf(GDALDataset& dataset) {
  if (!countable(dataset)) return storedBlockRanges(dataset);
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  auto blocks = std::make_shared<BlockRanges>(width, height, BlockRanges::blockTexelsFor(width, height));
  const QuietGdalErrors quiet;  // as exactRawRange()
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  countBlocks(band, *blocks, [&](int first, int count) {
    visitWindow(band, 0, first, width, count,
                [&](int column, int row, double value) { blocks->count(column, row, value); });
  });
  return blocks;
}

std::optional<ValueRange> exactRawRange(GDALDataset& dataset, const healpix::PageRanges* ranges) {
  if (!ranges) return exactRawRange(dataset);
  const healpix::PageRanges::Range whole = ranges->whole();
  if (whole.least > whole.greatest) return std::nullopt;
  return ValueRange{whole.least, whole.greatest};
}

}  // namespace strata::gdal
