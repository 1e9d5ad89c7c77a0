#pragma once
#include <optional>

#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/raster_layer.hpp>

namespace strata::gdal {

// The geographic extent of `dataset` from its georeferencing: its geotransform in a geographic
// (longitude, latitude) CRS on any body. Throws strata::Error at `where` for a projected CRS (not yet
// supported), rotated grids, or a raster without georeferencing that is not 2:1 (then `extent` must be
// given). A 2:1 raster without georeferencing is taken as global equirectangular.
GeographicExtent extentOf(GDALDataset& dataset, const SourceLocation& where);

// Checks an extent the pipeline gives: [west, south, east, north] in degrees.
GeographicExtent extentFromParameter(const std::vector<double>& values, const SourceLocation& where);

}  // namespace strata::gdal
