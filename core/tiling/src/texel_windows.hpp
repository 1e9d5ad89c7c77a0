#pragma once
#include <functional>
#include <vector>

#include <gdal_priv.h>

namespace strata::tiling {

// One window of band 1 at full resolution: its values, and its mask band's (0: no data there).
struct TexelWindow {
  int x = 0, y = 0, width = 0, height = 0;
  std::vector<double> values;  // row-major, width x height
  std::vector<GByte> mask;
};

// Reads band 1 of `raster` window by window, windows of a page (512 x 512) row by row, for `visit`. Throws
// strata::Error naming the file when a window cannot be read.
void visitTexelWindows(GDALDataset& raster, const std::function<void(const TexelWindow&)>& visit);

}  // namespace strata::tiling
