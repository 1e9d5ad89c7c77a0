#pragma once
#include <cstdint>
#include <memory>
#include <optional>

#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/plugin_registry.hpp>
#include <strata/plugin/raster_georeference.hpp>

namespace strata::gdal {

// A HEALPix pyramid as its metadata describes it (strata/plugin/healpix_pyramid.hpp).
struct HealpixPyramidFile {
  std::int64_t nside = 0;
  std::optional<healpix::FaceWindow> window;  // the part of one face it holds, if not the whole strip
  RasterGeoreference georeference;            // the strip's projection, and the geotransform of the strip or the window
  std::shared_ptr<const healpix::PageRanges> ranges;  // the pages' true ranges, where the file holds them
};

// What `dataset` says of itself as a HEALPix pyramid; empty for any other raster. Throws strata::Error at
// `where` for a file that says it is one but whose size or metadata do not agree.
std::optional<HealpixPyramidFile> healpixPyramidOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                                   const SourceLocation& where);

}  // namespace strata::gdal
