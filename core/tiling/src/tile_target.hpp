#pragma once
#include <memory>
#include <string>

#include <ogr_spatialref.h>

#include <strata/plugin/plugin_registry.hpp>

namespace strata::tiling {

// The --to name of the HEALPix pyramid (strata/plugin/healpix_pyramid.hpp), a layout rather than a projection: the
// planar HEALPix projection is the CRS "+proj=healpix".
inline constexpr const char* kHealpixPyramid = "healpix";

using Transformation = std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation*)>;

// From `crs` to longitude and latitude in degrees on its own datum, x east and y north; null when PROJ
// has none.
Transformation geographicTransformation(const OGRSpatialReference& crs);

// The raster's ellipsoid as PROJ terms (" +R=..." or " +a=... +rf=..."): the figure every target keeps.
std::string figureTerms(const OGRSpatialReference& crs);

// The CRS a raster is tiled into, as a PROJ string on the raster's own ellipsoid: `target` when given
// (a projection name or a CRS), the raster's own CRS when it is one of the registered projections
// (empty: no reprojection), else the best-suited built-in one: polar stereographic for a raster that
// holds a pole or lies beyond 60 degrees of latitude, longitude/latitude for the rest.
std::string tileTarget(const PluginRegistry& plugins, const OGRSpatialReference& crs, const double geotransform[6],
                       int width, int height, const std::string& target, const SourceLocation& where);

}  // namespace strata::tiling
