#pragma once
#include <gdal_priv.h>

#include <optional>
#include <vector>

namespace strata::gdal {

// The texels of the window [column, column + columns) x [row, row + rows) of `band` as they can be drawn:
// row-major, NaN where the band's mask hides a texel or its value is not finite (pages mask those alike:
// raster_reading.cpp); nothing where GDAL cannot read the window.
std::optional<std::vector<double>> readDrawnWindow(GDALRasterBand& band, int column, int row, int columns, int rows);

}  // namespace strata::gdal
