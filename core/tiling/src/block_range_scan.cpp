#include "block_range_scan.hpp"

#include <cmath>

#include "texel_windows.hpp"

namespace strata::tiling {

BlockRanges scanBlockRanges(GDALDataset& raster) {
  const int width = raster.GetRasterXSize(), height = raster.GetRasterYSize();
  BlockRanges blocks(width, height, BlockRanges::blockTexelsFor(width, height));
  visitTexelWindows(raster, [&](const TexelWindow& window) {
    for (std::size_t i = 0; i < window.values.size(); ++i)
      if (window.mask[i] != 0 && std::isfinite(window.values[i]))
        blocks.count(window.x + int(i % std::size_t(window.width)), window.y + int(i / std::size_t(window.width)),
                     window.values[i]);
  });
  return blocks;
}

std::vector<std::pair<std::string, std::string>> blockRangeItems(GDALDataset& raster) {
  return scanBlockRanges(raster).metadataItems();
}

}  // namespace strata::tiling
