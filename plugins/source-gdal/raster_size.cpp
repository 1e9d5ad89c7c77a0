#include "raster_size.hpp"

#include <algorithm>
#include <string>

#include <cpl_string.h>

#include <strata/plugin/page_pyramid.hpp>

namespace strata::gdal {
namespace {

// 256 MiB: four times GDAL's block cache as source.gdal sets it; a 512 x 512 tile of 4 Float64 bands is 8 MiB.
constexpr double kMostBlockBytes = 256.0 * 1024 * 1024;
// 2^30 texels (32768 x 32768): tens of seconds of reading for one page at best, hours for a damaged file.
constexpr double kMostTexelsAveraged = 1024.0 * 1024 * 1024;

std::string mebibytes(double bytes) { return std::to_string(static_cast<long long>(bytes / (1024 * 1024))); }

// What GDAL allocates to read one block: of every band at once where they are interleaved by pixel.
double blockBytes(GDALDataset& dataset) {
  const char* interleave = dataset.GetMetadataItem("INTERLEAVE", "IMAGE_STRUCTURE");
  const bool byPixel = interleave && EQUAL(interleave, "PIXEL");
  double total = 0.0;
  for (int i = 1; i <= dataset.GetRasterCount(); ++i) {
    GDALRasterBand& band = *dataset.GetRasterBand(i);
    int width = 0, height = 0;
    band.GetBlockSize(&width, &height);
    const double bytes = double(width) * height * GDALGetDataTypeSizeBytes(band.GetRasterDataType());
    total = byPixel ? total + bytes : std::max(total, bytes);
  }
  return total;
}

// The texels GDAL averages into the coarsest page: those of the smallest overview still a page across
// (GDAL reads the overview nearest the reduction, from the finer side), or of the raster itself.
double coarsestPageTexels(GDALRasterBand& band) {
  double texels = double(band.GetXSize()) * band.GetYSize();
  for (int i = 0; i < band.GetOverviewCount(); ++i)
    if (GDALRasterBand* overview = band.GetOverview(i))
      if (std::max(overview->GetXSize(), overview->GetYSize()) >= kPagePayload)
        texels = std::min(texels, double(overview->GetXSize()) * overview->GetYSize());
  return texels;
}

}  // namespace

void checkPageableSize(GDALDataset& dataset, const SourceLocation& where) {
  const std::string file = dataset.GetDescription();
  const std::string size = std::to_string(dataset.GetRasterXSize()) + "x" + std::to_string(dataset.GetRasterYSize());
  if (const double bytes = blockBytes(dataset); bytes > kMostBlockBytes)
    throw Error(where,
                "'" + file + "' (" + size + ") is stored in blocks of " + mebibytes(bytes) +
                    " MiB, too large to read pages from (at most " + mebibytes(kMostBlockBytes) + " MiB)",
                "write it as tiles: `strata tile " + file + " OUTPUT.tif`, or gdal_translate -co TILED=YES");
  if (coarsestPageTexels(*dataset.GetRasterBand(1)) > kMostTexelsAveraged)
    throw Error(
        where,
        "'" + file + "' (" + size + ") has no overviews down to a page, so its coarsest page would average " +
            "more than 2^30 texels",
        "write it as a tiled pyramid: `strata tile " + file + " OUTPUT.tif`, or add overviews: gdaladdo " + file);
}

}  // namespace strata::gdal
