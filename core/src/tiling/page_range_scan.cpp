#include "tiling/page_range_scan.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <strata/error.hpp>

namespace strata::tiling {
namespace {

using Range = healpix::PageRanges::Range;

Range rangeOf(const std::vector<float>& values, const std::vector<GByte>& mask) {
  Range range{INFINITY, -INFINITY, false};
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (mask[i] == 0 || std::isnan(values[i])) {
      range.uncovered = true;
      continue;
    }
    range.least = std::min(range.least, values[i]);
    range.greatest = std::max(range.greatest, values[i]);
  }
  return range;
}

}  // namespace

healpix::PageRanges scanPageRanges(GDALDataset& strip, std::int64_t nside) {
  GDALRasterBand& band = *strip.GetRasterBand(1);
  const int pagesAcross = int(12 * nside / kPagePayload), pagesDown = int(nside / kPagePayload);
  std::vector<float> values(std::size_t(kPagePayload) * kPagePayload);
  std::vector<GByte> mask(values.size());
  std::vector<Range> finest;
  finest.reserve(std::size_t(pagesAcross) * std::size_t(pagesDown));
  for (int row = 0; row < pagesDown; ++row)
    for (int column = 0; column < pagesAcross; ++column) {
      const int x = column * kPagePayload, y = row * kPagePayload;
      CPLErrorReset();
      if (band.RasterIO(GF_Read, x, y, kPagePayload, kPagePayload, values.data(), kPagePayload, kPagePayload,
                        GDT_Float32, 0, 0) != CE_None ||
          band.GetMaskBand()->RasterIO(GF_Read, x, y, kPagePayload, kPagePayload, mask.data(), kPagePayload,
                                       kPagePayload, GDT_Byte, 0, 0) != CE_None)
        throw Error({strip.GetDescription()}, "GDAL could not read back the strip's page at column " +
                                                  std::to_string(column) + ", row " + std::to_string(row) + ": " +
                                                  CPLGetLastErrorMsg(),
                    "check that the disk has room and is not failing");
      finest.push_back(rangeOf(values, mask));
    }
  return healpix::PageRanges(nside, finest);
}

}  // namespace strata::tiling
