#include "value_range.hpp"

#include <cpl_string.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "quiet_gdal_errors.hpp"

namespace strata::gdal {
namespace {

// 16 million texels: a 4096 x 4096 raster, read whole in well under a second.
constexpr double kCountableTexels = 16.0 * 1024 * 1024;

bool finite(const ValueRange& range) { return std::isfinite(range.least) && std::isfinite(range.greatest); }

// The extremes of the finite values the mask lets through: GDAL's own count takes in infinities, which
// pages mask as they mask NaN (raster_reading.cpp), so they bound nothing that is drawn.
std::optional<ValueRange> finiteRange(GDALRasterBand& band) {
  const int width = band.GetXSize(), height = band.GetYSize();
  std::vector<float> values(std::size_t(width) * std::size_t(height));
  std::vector<GByte> valid(values.size());
  if (band.RasterIO(GF_Read, 0, 0, width, height, values.data(), width, height, GDT_Float32, 0, 0) != CE_None ||
      band.GetMaskBand()->RasterIO(GF_Read, 0, 0, width, height, valid.data(), width, height, GDT_Byte, 0, 0) !=
          CE_None)
    return std::nullopt;
  std::optional<ValueRange> range;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!valid[i] || !std::isfinite(values[i])) continue;
    const double value = values[i];
    range = range ? ValueRange{std::min(range->least, value), std::max(range->greatest, value)} : ValueRange{value, value};
  }
  return range;
}

std::optional<ValueRange> countedRange(GDALRasterBand& band) {
  double extremes[2] = {0.0, 0.0};
  if (band.ComputeRasterMinMax(FALSE, extremes) != CE_None) return std::nullopt;
  const ValueRange range{extremes[0], extremes[1]};
  return finite(range) ? range : finiteRange(band);
}

}  // namespace

std::optional<ValueRange> exactRawRange(GDALDataset& dataset) {
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  const char* approximate = band.GetMetadataItem("STATISTICS_APPROXIMATE");
  int hasLeast = 0, hasGreatest = 0;
  const double least = band.GetMinimum(&hasLeast), greatest = band.GetMaximum(&hasGreatest);
  if (hasLeast && hasGreatest && !(approximate && CPLTestBool(approximate)) && finite({least, greatest}))
    return ValueRange{least, greatest};
  if (double(dataset.GetRasterXSize()) * dataset.GetRasterYSize() > kCountableTexels) return std::nullopt;
  const QuietGdalErrors quiet;  // a file that cannot be read whole is reported page by page when drawn
  return countedRange(band);
}

}  // namespace strata::gdal
