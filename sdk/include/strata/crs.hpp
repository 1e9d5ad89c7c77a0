#pragma once
#include <memory>
#include <strata/export.hpp>
#include <string>

#include <strata/error.hpp>
#include <strata/plugin/projection.hpp>

class OGRSpatialReference;

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// Recognises a coordinate reference system as one of the registered projections (built-in or from
// plugins), by the PROJ form of the CRS and its ellipsoid. `crs` is anything GDAL reads as a CRS: WKT, a
// PROJ string, "EPSG:3031". Throws strata::Error at `where` when the CRS cannot be read, uses units other
// than metres or degrees, or is a projection no registered type handles; the fix says how to reproject.
std::unique_ptr<Projection> projectionOfCrs(const PluginRegistry& plugins, const std::string& crs,
                                            const SourceLocation& where);
// The same for a CRS GDAL holds already, such as a raster's.
std::unique_ptr<Projection> projectionOfCrs(const PluginRegistry& plugins, const OGRSpatialReference& crs,
                                            const SourceLocation& where);

// Longitude/latitude in degrees: the projection of rasters placed by a geographic extent. The figure does
// not matter to a map in degrees.
std::unique_ptr<Projection> geographicProjection(const PluginRegistry& plugins);

// The PROJ string of a CRS, or "" when it has none.
std::string projStringOf(const OGRSpatialReference& crs);

}  // namespace strata
STRATA_EXPORTS_END
