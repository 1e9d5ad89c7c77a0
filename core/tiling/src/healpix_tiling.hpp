#pragma once
// `strata tile --to healpix`: the HEALPix pyramid of strata/plugin/healpix_pyramid.hpp, written face by face with
// GDAL's warper so that resampling, datums and the antimeridian are GDAL's.
#include <gdal_priv.h>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata::tiling {

// Writes `input` (georeferenced, with bands checkBands accepts) as the pyramid at request.output, at
// request.nside or the nside its finest texels need. Throws strata::Error naming the file and what to do.
TilingResult tileHealpix(const PluginRegistry& plugins, GDALDataset& input, const TilingRequest& request);

}  // namespace strata::tiling
