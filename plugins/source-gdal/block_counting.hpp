#pragma once
#include <gdal_priv.h>

#include <functional>

#include <strata/plugin/block_ranges.hpp>

namespace strata::gdal {

// Rows [first, first + count) of band 1 that could not be read whole: counted as can be.
using UnreadableRows = std::function<void(int first, int count)>;

// Counts band 1 into `blocks` in one pass over the file, in bands of rows each read with the rows just above and
// below it: every texel that can be drawn (BlockRanges::count) and the texels' bends (BlockRanges::countBends),
// where no data is drawn (nodata, masked, not finite) counting as a gap. A band that cannot be read whole goes to
// `unreadable`, and every bend stays unknown: what is drawn there is not known here.
void countBlocks(GDALRasterBand& band, BlockRanges& blocks, const UnreadableRows& unreadable);

}  // namespace strata::gdal
