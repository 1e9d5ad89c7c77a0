#pragma once
#include <gdal_priv.h>

#include <string>

#include <strata/body.hpp>
#include <strata/error.hpp>

namespace strata::gdal {

// Warns (strata/log.hpp) where the raster's CRS (`crs` where the source gives one, else the file's) lies on
// a body of another size than the pipeline's `body`: a Mars map drawn on the Earth. The raster is still
// drawn, placed by its longitudes and latitudes, which hold on a sphere of any size: a body may be shown at
// a radius of its own choosing, and a map of one body may be draped on another on purpose. The CRS fits when
// the body's radius lies within 1% of its ellipsoid's semi-axes (strata/named_bodies.hpp's radiusFits).
void reportAnotherBody(GDALDataset& dataset, const std::string& crs, const Body& body, const SourceLocation& where);

}  // namespace strata::gdal
