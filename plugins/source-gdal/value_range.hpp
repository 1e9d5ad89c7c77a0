#pragma once
#include <memory>
#include <optional>

#include <gdal_priv.h>

#include <strata/plugin/block_ranges.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/layer.hpp>

namespace strata::gdal {

// The least and greatest finite raw values of band 1 that can be drawn (nodata and unreadable parts left
// out: the sphere shows there), where they can be known for certain: the file's own exact statistics, or a
// count over a raster small enough to read whole quickly. None for a large raster without them (GDAL's
// approximate statistics come from averaged overviews and miss the extremes).
std::optional<ValueRange> exactRawRange(GDALDataset& dataset);
// The same from the blocks blockRangesOf() gives, where the file holds no exact statistics.
std::optional<ValueRange> exactRawRange(GDALDataset& dataset, const BlockRanges& blocks);
// The ranges of band 1's blocks, by the same rules, and their texels' bends, for a raster small enough to read
// whole quickly; for a larger one those `strata tile` stored in it (stored_block_ranges.hpp; bends unknown), or null.
std::shared_ptr<BlockRanges> blockRangesOf(GDALDataset& dataset);
// The same for a HEALPix pyramid from the true page ranges `strata tile` stored in it (`ranges`, or null where
// it stored none), which need no reading.
std::optional<ValueRange> exactRawRange(GDALDataset& dataset, const healpix::PageRanges* ranges);

}  // namespace strata::gdal
