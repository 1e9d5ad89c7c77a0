#pragma once
#include <gdal_priv.h>

#include <strata/error.hpp>

namespace strata::gdal {

// Refuses, at `where`, a raster whose pages GDAL could not read in reasonable time and memory: one stored
// in blocks so large that reading any texel allocates hundreds of MiB, or one so large without overviews
// (or with only fine ones) that its coarsest page, which a layer shows first, would average billions of
// texels. Each error names the file and says how to rewrite it.
void checkPageableSize(GDALDataset& dataset, const SourceLocation& where);

}  // namespace strata::gdal
