#include "drawn_window.hpp"

#include <cmath>
#include <limits>

namespace strata::gdal {

std::optional<std::vector<double>> readDrawnWindow(GDALRasterBand& band, int column, int row, int columns, int rows) {
  std::vector<double> values(std::size_t(columns) * std::size_t(rows));
  std::vector<GByte> valid(values.size());
  if (band.RasterIO(GF_Read, column, row, columns, rows, values.data(), columns, rows, GDT_Float64, 0, 0) != CE_None ||
      band.GetMaskBand()->RasterIO(GF_Read, column, row, columns, rows, valid.data(), columns, rows, GDT_Byte, 0, 0) !=
          CE_None)
    return std::nullopt;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!valid[i] || !std::isfinite(values[i])) values[i] = std::numeric_limits<double>::quiet_NaN();
  return values;
}

}  // namespace strata::gdal
