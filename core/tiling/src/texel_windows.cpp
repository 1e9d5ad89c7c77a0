#include "texel_windows.hpp"

#include <algorithm>
#include <string>

#include <strata/error.hpp>
#include <strata/plugin/page_pyramid.hpp>

namespace strata::tiling {

void visitTexelWindows(GDALDataset& raster, const std::function<void(const TexelWindow&)>& visit) {
  GDALRasterBand& band = *raster.GetRasterBand(1);
  TexelWindow window;
  for (window.y = 0; window.y < band.GetYSize(); window.y += kPagePayload)
    for (window.x = 0; window.x < band.GetXSize(); window.x += kPagePayload) {
      window.width = std::min(kPagePayload, band.GetXSize() - window.x);
      window.height = std::min(kPagePayload, band.GetYSize() - window.y);
      window.values.resize(std::size_t(window.width) * std::size_t(window.height));
      window.mask.resize(window.values.size());
      CPLErrorReset();
      if (band.RasterIO(GF_Read, window.x, window.y, window.width, window.height, window.values.data(), window.width,
                        window.height, GDT_Float64, 0, 0) != CE_None ||
          band.GetMaskBand()->RasterIO(GF_Read, window.x, window.y, window.width, window.height, window.mask.data(),
                                       window.width, window.height, GDT_Byte, 0, 0) != CE_None)
        throw Error({raster.GetDescription()},
                    "GDAL could not read the texels at column " + std::to_string(window.x) + ", row " +
                        std::to_string(window.y) + ": " + CPLGetLastErrorMsg(),
                    "check that the file is whole (`gdalinfo -checksum` reads every block), and that the disk is "
                    "not failing");
      visit(window);
    }
}

}  // namespace strata::tiling
