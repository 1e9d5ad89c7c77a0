#pragma once
#include <string>
#include <utility>
#include <vector>

#include <gdal_priv.h>

#include <strata/plugin/block_ranges.hpp>

namespace strata::tiling {

// The ranges of band 1's blocks at full resolution, as large as a file stores them (strata/plugin/block_ranges.hpp),
// texels that hold data being those its mask band lets through and that are finite, as source.gdal draws them. Throws
// strata::Error naming the file when a part cannot be read.
BlockRanges scanBlockRanges(GDALDataset& raster);

// The metadata items that store them in the file written from `raster` (BlockRanges::metadataItems).
std::vector<std::pair<std::string, std::string>> blockRangeItems(GDALDataset& raster);

}  // namespace strata::tiling
