#pragma once
#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/port.hpp>
#include <strata/raster_layer.hpp>

namespace strata::gdal {

// The longest side a raster is read at. Larger rasters are averaged down by GDAL while reading; paging
// them at full resolution is the page cache's job. 8192 fits every OpenGL 4.5 GPU (which must offer
// 16384) and keeps a colour raster at 8192x4096 texels to 256 MiB of half floats.
inline constexpr int kLongestSide = 8192;

// Reads the whole raster as `kind` (colour kinds: 1 to 4 bands of 8 or 16 bits, taken as sRGB-encoded;
// other kinds: band 1, any numeric type). Coverage comes from GDAL's mask band (nodata, alpha band or
// mask file) and excludes NaN and infinite values. Throws strata::Error at `where`.
RasterImage readRaster(GDALDataset& dataset, LayerKind kind, const SourceLocation& where);

}  // namespace strata::gdal
