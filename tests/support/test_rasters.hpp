#pragma once
#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

namespace strata::test {

using Rgb8 = std::array<unsigned char, 3>;

// The colour of cell (column, row) of the test checkerboard: 8 columns of 45 degrees of longitude from
// -180, 4 rows of 45 degrees of latitude from the north. Every cell differs from every other by at least
// 24 levels in some channel, far above the rendering tolerance.
Rgb8 cellColour(int column, int row);

// Writes a global 256x128 RGB GeoTIFF (EPSG:4326) of the checkerboard.
void writeCheckerboard(const std::filesystem::path& file);

// Writes a one-band Float32 GeoTIFF of `width` x `height` over [west, south, east, north] (degrees, EPSG:4326)
// with value(column, row) per texel and an optional nodata value.
void writeFloatRaster(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                      const std::function<float(int column, int row)>& value, std::optional<double> nodata = {});

// Reads an 8-bit PNG or other raster back as rows of RGBA, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba;
  std::array<int, 4> at(int x, int y) const;
};
Image readImage(const std::filesystem::path& file);

}  // namespace strata::test
