#pragma once
#include <cstdint>

#include <gdal_priv.h>

#include <strata/plugin/healpix_pyramid.hpp>

namespace strata::tiling {

// The true ranges of a one-channel HEALPix strip's pages (healpix::PageRanges), from band 1's values at full
// resolution, its mask band (nodata, NaN) saying which texels hold none. Throws strata::Error naming the
// file when a page cannot be read.
healpix::PageRanges scanPageRanges(GDALDataset& strip, std::int64_t nside);

}  // namespace strata::tiling
