#pragma once
#include <cstddef>
#include <span>

#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/plugin/page_source.hpp>
#include <strata/plugin/port.hpp>

namespace strata::gdal {

// Checks, when the source opens, that `dataset` can be read as `kind` (colour kinds: 1 to 4 bands of 8
// or 16 bits, in any colour space; other kinds: band 1, any numeric type), that its nodata values fit
// its bands, and that its pages can be read (checkPageableSize). Throws strata::Error at `where`.
void checkRaster(GDALDataset& dataset, LayerKind kind, const SourceLocation& where);

// The page format a layer of `kind` is stored in.
PageFormat pageFormatOf(LayerKind kind);

// A rectangle of the raster's own texels.
struct RasterWindow {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

// Reads `window` averaged down to `width` x `height` texels (GDAL takes them from the overview nearest
// in resolution when the file has overviews) into `texels`, in pageFormatOf(kind); colours as they are
// encoded, scaled to [0, 1] (the page cache converts them to scene-linear on the GPU). Coverage comes from
// GDAL's mask band (nodata, alpha band or mask file) and excludes NaN and infinite values. Throws
// std::runtime_error naming the file when GDAL cannot read it.
void readWindow(GDALDataset& dataset, LayerKind kind, const RasterWindow& window, int width, int height,
                std::span<std::byte> texels);

}  // namespace strata::gdal
