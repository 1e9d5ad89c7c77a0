#pragma once
#include <memory>

#include <gdal_priv.h>

#include <strata/plugin/block_ranges.hpp>

namespace strata::gdal {

// The block ranges `strata tile` stored in the file (BlockRanges::metadataItems), where the file's coarsest
// overview agrees with them; null where it stored none. Each overview texel over blocks full of data is an
// average of their texels and so lies within their ranges: a file changed after tiling (rescaled by
// gdal_translate, say, which copies the metadata) almost surely contradicts them, and is then warned of and
// bounded by nothing.
std::shared_ptr<BlockRanges> storedBlockRanges(GDALDataset& dataset);

}  // namespace strata::gdal
