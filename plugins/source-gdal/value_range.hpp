#pragma once
#include <optional>

#include <gdal_priv.h>

#include <strata/layer.hpp>

namespace strata::gdal {

// The least and greatest finite raw values of band 1, nodata left out, where they can be known for certain: the
// file's own exact statistics, or GDAL's exact count over a raster small enough to read whole quickly.
// None for a large raster without them (GDAL's approximate statistics come from averaged overviews and
// miss the extremes).
std::optional<ValueRange> exactRawRange(GDALDataset& dataset);

}  // namespace strata::gdal
