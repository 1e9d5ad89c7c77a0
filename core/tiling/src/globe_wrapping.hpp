#pragma once
// A longitude/latitude raster that goes round the globe, seen with its own texels around it: GDAL's warper
// does not wrap, and beyond the outermost texel centres its bilinear kernel holds the edge texel's value
// (or, exactly on the antimeridian, finds no texel at all).
#include <gdal_priv.h>

#include "cog_writing.hpp"

namespace strata::tiling {

// A VRT of `input` from longitude -180 to 180 with one column more on each side, taken across the
// antimeridian, and, where an edge is a pole, one row more taken across the pole (the texels half a turn of
// longitude away), so that bilinear interpolation there is as good as anywhere. Null unless `input` is an
// unrotated longitude/latitude raster 360 degrees wide. It refers to `input`, which must outlive it.
Dataset wrapAroundGlobe(GDALDataset& input);

}  // namespace strata::tiling
