#include "value_range.hpp"

#include <cpl_string.h>

#include "quiet_gdal_errors.hpp"

namespace strata::gdal {
namespace {

// 16 million texels: a 4096 x 4096 raster, read whole in well under a second.
constexpr double kCountableTexels = 16.0 * 1024 * 1024;

}  // namespace

std::optional<ValueRange> exactRawRange(GDALDataset& dataset) {
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  const char* approximate = band.GetMetadataItem("STATISTICS_APPROXIMATE");
  int hasLeast = 0, hasGreatest = 0;
  const double least = band.GetMinimum(&hasLeast), greatest = band.GetMaximum(&hasGreatest);
  if (hasLeast && hasGreatest && !(approximate && CPLTestBool(approximate))) return ValueRange{least, greatest};
  if (double(dataset.GetRasterXSize()) * dataset.GetRasterYSize() > kCountableTexels) return std::nullopt;
  double extremes[2] = {0.0, 0.0};
  const QuietGdalErrors quiet;  // a file that cannot be read whole is reported page by page when drawn
  if (band.ComputeRasterMinMax(FALSE, extremes) != CE_None) return std::nullopt;
  return ValueRange{extremes[0], extremes[1]};
}

}  // namespace strata::gdal
