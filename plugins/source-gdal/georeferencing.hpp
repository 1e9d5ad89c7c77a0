#pragma once
#include <string>
#include <vector>

#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/plugin/plugin_registry.hpp>
#include <strata/plugin/raster_georeference.hpp>

namespace strata::gdal {

// What the pipeline says about where a raster lies, beside what the file says.
struct GeoreferenceOptions {
  std::string crs;  // replaces the file's CRS when not empty (WKT, PROJ string, EPSG:code)
  SourceLocation crsWhere;
  std::vector<double> extent;  // [west, south, east, north] in degrees for a lon/lat raster, or empty
  SourceLocation extentWhere;
  SourceLocation fileWhere;  // the `path` parameter, for problems of the file itself
};

// The projection and geotransform of `dataset`, a raster of `dataset`'s size: its CRS recognised as one of
// the registered projections (the options' CRS when given) and its north-up geotransform (or the
// options' extent). A raster with neither CRS nor geotransform is longitude/latitude, global when 2:1.
// Throws strata::Error naming the parameter or the file, with a fix, for what cannot be placed.
RasterGeoreference georeferenceOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                  const GeoreferenceOptions& options);

}  // namespace strata::gdal
