#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gdal.h>

namespace strata::test {

using Rgb8 = std::array<unsigned char, 3>;
using Rgb16 = std::array<std::uint16_t, 3>;

// The colour of cell (column, row) of the test checkerboard: 8 columns of 45 degrees of longitude from
// -180, 4 rows of 45 degrees of latitude from the north. Every cell differs from every other by at least
// 24 levels in some channel, far above the rendering tolerance.
Rgb8 cellColour(int column, int row);

// Writes a global 256x128 RGB GeoTIFF (EPSG:4326) of the checkerboard.
void writeCheckerboard(const std::filesystem::path& file);

// Writes an RGB GeoTIFF of `width` x `height` over [west, south, east, north] (degrees, EPSG:4326) with
// colour(column, row) per texel.
void writeColourRaster(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                       const std::function<Rgb8(int column, int row)>& colour);
// The same with 16-bit bands, for colours whose encoding needs more than 8 bits (linear light).
void writeColourRaster16(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                         const std::function<Rgb16(int column, int row)>& colour);

// Writes a one-band Float32 GeoTIFF of `width` x `height` over [west, south, east, north] (degrees, EPSG:4326)
// with value(column, row) per texel and an optional nodata value.
void writeFloatRaster(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                      const std::function<float(int column, int row)>& value, std::optional<double> nodata = {});

// A GeoTIFF of any CRS, band count and sample type, for tests of reading and tiling.
struct RasterFileSpec {
  std::string crs;  // anything OGRSpatialReference::SetFromUserInput reads
  std::array<double, 6> geotransform;
  int width = 600;
  int height = 300;
  int bands = 1;
  GDALDataType type = GDT_Float32;
  std::optional<double> nodata = 255.0;
  std::vector<std::string> creationOptions = {};  // e.g. "TILED=YES", "COMPRESS=DEFLATE"
  bool values = true;  // false: no texel written (with SPARSE_OK=TRUE a file of kilobytes, read as nodata)
};

// The value the writer stores at (column, row) of band `band`: distinct per texel and band, below 251, so a
// lossless copy is recognisable and nodata 255 never occurs in the data.
double rasterFileValue(int column, int row, int band);

void writeRasterFile(const std::filesystem::path& file, const RasterFileSpec& spec);

// Reads an 8-bit PNG or other raster back as rows of RGBA, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba;
  std::array<int, 4> at(int x, int y) const;
};
Image readImage(const std::filesystem::path& file);

}  // namespace strata::test
