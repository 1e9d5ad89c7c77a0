#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <strata/export.hpp>
#include <string>

#include <strata/error.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// What `strata tile` is asked to do (docs/architecture.md, "Data and paging").
struct TilingRequest {
  std::filesystem::path input;   // any raster GDAL opens: 1 to 4 bands of 8/16/32-bit integers or floats
  std::filesystem::path output;  // the Cloud Optimized GeoTIFF to write
  // Empty: keep the input's CRS when it is a registered projection, else reproject into the best-suited
  // one. Otherwise a projection name (equirectangular, polar-north, polar-south), any CRS GDAL reads (WKT,
  // PROJ string, EPSG:code), used as given, or "healpix": the HEALPix pyramid of strata/plugin/healpix_pyramid.hpp.
  std::string target;
  bool overwrite = false;  // without it an existing output is an error: nothing a user wrote is replaced
  // Called with the fraction done; empty: quiet.
  std::function<void(double)> progress;
  // The HEALPix pyramid's nside: a power of two from healpix::kLeastNside to 2^30 (above 2^26, a window of
  // one face: strata/plugin/healpix_pyramid.hpp). 0: the least whose texels are no larger than the input's finest.
  std::int64_t nside = 0;
};

struct TilingResult {
  std::string crs;  // the output's CRS as a PROJ string; a HEALPix pyramid's figure (healpix::kFigureItem)
  bool reprojected = false;
  int width = 0;
  int height = 0;
  int overviews = 0;
  std::int64_t nside = 0;  // of a HEALPix pyramid; 0 for any other output
};

// Writes the on-disk pyramid the page cache reads: a Cloud Optimized GeoTIFF with 512x512 internal tiles,
// averaged overviews down to one tile and lossless compression, through GDAL's COG driver, reprojecting
// with GDAL's warper where needed, on all cores. Throws strata::Error naming the file and what to do.
TilingResult tileRaster(const PluginRegistry& plugins, const TilingRequest& request);

}  // namespace strata
STRATA_EXPORTS_END
