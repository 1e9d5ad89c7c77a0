#pragma once
#include <gdal_priv.h>

#include <strata/plugin/block_ranges.hpp>

namespace strata::gdal {

// Counts the bends of band 1's texels into `blocks` (BlockRanges::countBends), reading the raster in bands of
// rows, each with the rows just above and below it; where no data is drawn (nodata, masked, not finite) counts
// as a gap. Where some rows cannot be read, every bend stays unknown: what is drawn there is not known here.
void countTexelBends(GDALRasterBand& band, BlockRanges& blocks);

}  // namespace strata::gdal
