#include "raster_reading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace strata::gdal {
namespace {

struct ReadSize {
  int width;
  int height;
};

ReadSize readSize(GDALDataset& dataset) {
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  const int longest = std::max(width, height);
  if (longest <= kLongestSide) return {width, height};
  const double factor = double(kLongestSide) / longest;
  ReadSize size{std::max(1, int(width * factor)), std::max(1, int(height * factor))};
  std::fprintf(stderr, "strata: source.gdal reads '%s' (%dx%d) averaged down to %dx%d\n", dataset.GetDescription(),
               width, height, size.width, size.height);
  return size;
}

// One band (or its mask) read as floats at `size`, averaged where it is reduced.
std::vector<float> readBand(GDALRasterBand& band, ReadSize size, const SourceLocation& where) {
  std::vector<float> values(static_cast<std::size_t>(size.width) * static_cast<std::size_t>(size.height));
  GDALRasterIOExtraArg extra;
  INIT_RASTERIO_EXTRA_ARG(extra);
  extra.eResampleAlg = GRIORA_Average;
  CPLErrorReset();
  if (band.RasterIO(GF_Read, 0, 0, band.GetXSize(), band.GetYSize(), values.data(), size.width, size.height,
                    GDT_Float32, 0, 0, &extra) != CE_None)
    throw Error(where, "cannot read '" + std::string(band.GetDataset() ? band.GetDataset()->GetDescription() : "") +
                           "': " + CPLGetLastErrorMsg(),
                "check that the file is complete and readable (gdalinfo -checksum FILE)");
  return values;
}

// Coverage per texel in [0, 1] from the mask band of band 1 (0 or 255, averaged where reduced).
std::vector<float> readCoverage(GDALRasterBand& band, ReadSize size, const SourceLocation& where) {
  std::vector<float> coverage = readBand(*band.GetMaskBand(), size, where);
  for (float& c : coverage) c /= 255.0f;
  return coverage;
}

float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

RasterImage readColour(GDALDataset& dataset, ReadSize size, const SourceLocation& where) {
  const int bands = dataset.GetRasterCount();
  GDALRasterBand& first = *dataset.GetRasterBand(1);
  const GDALDataType type = first.GetRasterDataType();
  if (type != GDT_Byte && type != GDT_UInt16)
    throw Error(where, "'" + std::string(dataset.GetDescription()) + "' holds " + GDALGetDataTypeName(type) +
                           " values, but a colour layer needs 8 or 16-bit bands",
                "use `kind: scalar` for measurements, or convert: gdal_translate -ot Byte -scale");
  const float full = type == GDT_Byte ? 255.0f : 65535.0f;
  std::array<std::vector<float>, 3> rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = readBand(*dataset.GetRasterBand(bands >= 3 ? c + 1 : 1), size, where);
  std::vector<float> coverage = readCoverage(first, size, where);
  RasterImage image{size.width, size.height, 4, {}};
  image.texels.resize(coverage.size() * 4);
  for (std::size_t i = 0; i < coverage.size(); ++i) {
    for (int c = 0; c < 3; ++c) image.texels[i * 4 + c] = srgbToLinear(rgb[c][i] / full) * coverage[i];
    image.texels[i * 4 + 3] = coverage[i];
  }
  return image;
}

RasterImage readValues(GDALDataset& dataset, ReadSize size, const SourceLocation& where) {
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  std::vector<float> values = readBand(band, size, where);
  std::vector<float> coverage = readCoverage(band, size, where);
  RasterImage image{size.width, size.height, 2, {}};
  image.texels.resize(values.size() * 2);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float c = std::isfinite(values[i]) ? coverage[i] : 0.0f;
    image.texels[i * 2] = c > 0.0f ? values[i] * c : 0.0f;
    image.texels[i * 2 + 1] = c;
  }
  return image;
}

// A nodata value that no sample of the band's type can hold masks nothing: the file says "these texels
// are missing" in a way that cannot be honoured, almost always a mistake made when it was written.
void checkNodata(GDALRasterBand& band, const SourceLocation& where) {
  int declared = 0;
  const double nodata = band.GetNoDataValue(&declared);
  const GDALDataType type = band.GetRasterDataType();
  if (!declared || std::isnan(nodata)) return;
  int clamped = 0, rounded = 0;  // GDAL reports whether storing the value would clamp or round it
  GDALAdjustValueToDataType(type, nodata, &clamped, &rounded);
  if (!clamped && !rounded) return;
  std::array<char, 64> value{};
  std::snprintf(value.data(), value.size(), "%.9g", nodata);
  const std::string file = band.GetDataset() ? band.GetDataset()->GetDescription() : "";
  throw Error(where,
              "'" + file + "' band " + std::to_string(band.GetBand()) + " declares nodata " + value.data() + ", which no " +
                  GDALGetDataTypeName(type) + " sample can hold, so it would mask nothing",
              "set the value the file really uses: gdal_edit.py -a_nodata VALUE " + file +
                  ", or remove it: gdal_edit.py -unsetnodata " + file);
}

}  // namespace

RasterImage readRaster(GDALDataset& dataset, LayerKind kind, const SourceLocation& where) {
  if (dataset.GetRasterCount() < 1 || dataset.GetRasterXSize() < 1 || dataset.GetRasterYSize() < 1)
    throw Error(where, "'" + std::string(dataset.GetDescription()) + "' has no raster data",
                "point `path` at a raster (gdalinfo FILE lists its bands)");
  for (int band = 1; band <= dataset.GetRasterCount(); ++band) checkNodata(*dataset.GetRasterBand(band), where);
  ReadSize size = readSize(dataset);
  const bool colour = kind == LayerKind::Color;
  return colour ? readColour(dataset, size, where) : readValues(dataset, size, where);
}

}  // namespace strata::gdal
