#include "texel_bends.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace strata::gdal {
namespace {

constexpr int kRowsAtATime = 256;  // as value_range.cpp reads: 4 MiB of floats for a 4096-wide raster

// Rows [first, first + count) of band 1 as doubles, NaN where no data is drawn; false where they cannot be read.
bool readRows(GDALRasterBand& band, int first, int count, std::vector<std::vector<double>>& rows) {
  const int width = band.GetXSize();
  std::vector<float> values(std::size_t(width) * std::size_t(count));
  std::vector<GByte> valid(values.size());
  if (band.RasterIO(GF_Read, 0, first, width, count, values.data(), width, count, GDT_Float32, 0, 0) != CE_None ||
      band.GetMaskBand()->RasterIO(GF_Read, 0, first, width, count, valid.data(), width, count, GDT_Byte, 0, 0) !=
          CE_None)
    return false;
  for (int row = 0; row < count; ++row) {
    std::vector<double> line(std::size_t(width), std::numeric_limits<double>::quiet_NaN());
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(row) * std::size_t(width) + std::size_t(x);
      if (valid[i] && std::isfinite(values[i])) line[std::size_t(x)] = values[i];
    }
    rows.push_back(std::move(line));
  }
  return true;
}

}  // namespace

void countTexelBends(GDALRasterBand& band, BlockRanges& blocks) {
  const int height = band.GetYSize();
  for (int row = 1; row + 1 < height; row += kRowsAtATime) {
    const int last = std::min(row + kRowsAtATime, height - 1);  // the band's rows [row, last), their neighbours too
    std::vector<std::vector<double>> rows;
    if (!readRows(band, row - 1, last - row + 2, rows)) {
      blocks.forgetBends();
      return;
    }
    for (int y = row; y < last; ++y)
      blocks.countBends(y, rows[std::size_t(y - row)], rows[std::size_t(y - row + 1)], rows[std::size_t(y - row + 2)]);
  }
}

}  // namespace strata::gdal
