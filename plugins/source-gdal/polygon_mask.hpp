#pragma once
#include <memory>
#include <string>

#include <gdal_priv.h>

#include <strata/error.hpp>

#include "memory_file.hpp"

namespace strata::gdal {

// Which polygons of a vector file to burn into a mask, and how finely.
struct PolygonMaskOptions {
  std::string layer;  // the vector layer's name; empty: the file's first
  SourceLocation layerWhere;
  int texels = 0;            // along the longer side of the polygons' extent
  bool crsGiven = false;     // the pipeline gives the CRS (`projection`), so the file need not
  SourceLocation fileWhere;  // the `path` parameter
};

// A vector file's polygons burnt into a one-band Float32 raster by GDAL's rasteriser: 1 inside (texel centres
// within a polygon), 0 outside, over the polygons' extent in the layer's CRS. With `kind: mask` it is then a
// layer like any raster, paged from `raster` and averaged into coarser levels, so soft edges come from the
// pyramid (composite.overlay_mask feathers them) and the polygons cost nothing per pixel beyond a texture
// fetch, however many vertices they have.
struct PolygonMask {
  std::shared_ptr<const MemoryFile> file;  // holds the raster; must outlive every dataset opened from it
  std::unique_ptr<GDALDataset> raster;     // `file`, opened read-only
};

// Throws strata::Error naming the file and what to do when it has no such layer, no polygons, or no CRS
// (and the pipeline gives none).
PolygonMask rasterisePolygons(GDALDataset& vector, const PolygonMaskOptions& options);

}  // namespace strata::gdal
