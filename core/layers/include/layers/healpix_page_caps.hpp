#pragma once
#include <memory>

#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/raster_georeference.hpp>

#include "layers/block_caps.hpp"

namespace strata {

// A HEALPix pyramid's stored page ranges (healpix::PageRanges, those of its finest stored level) as block caps
// over its strip of faces (`georeference`: the strip's, nside texels high), so that a layer on the strip answers
// RegionalValueLayer::valuesWithin as a raster with block ranges does: an icosahedral patch over a HEALPix pyramid of
// heights is measured on the heights there.
std::shared_ptr<const BlockCaps> pageCapsOf(const healpix::PageRanges& ranges, const RasterGeoreference& georeference,
                                            int nside);

}  // namespace strata
