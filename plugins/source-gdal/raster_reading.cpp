#include "raster_reading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "raster_size.hpp"

namespace strata::gdal {
namespace {

// One band (or its mask) of `window` read as floats at width x height, averaged by GDAL where it is reduced.
std::vector<float> readReduced(GDALRasterBand& band, const RasterWindow& window, int width, int height) {
  std::vector<float> values(std::size_t(width) * std::size_t(height));
  GDALRasterIOExtraArg extra;
  INIT_RASTERIO_EXTRA_ARG(extra);
  extra.eResampleAlg = GRIORA_Average;
  CPLErrorReset();
  if (band.RasterIO(GF_Read, window.x, window.y, window.width, window.height, values.data(), width, height, GDT_Float32,
                    0, 0, &extra) != CE_None)
    throw std::runtime_error(CPLGetLastErrorMsg());
  return values;
}

// Whether `values` hold two different finite values: an edge, of data or of a mask.
bool holdsAnEdge(const std::vector<float>& values) {
  const auto first = std::find_if(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
  return std::any_of(first, values.end(), [&](float v) { return std::isfinite(v) && v != *first; });
}

// `finer` x `finer` blocks of `values` (width * finer wide) averaged into width x height.
std::vector<float> boxAveraged(const std::vector<float>& values, int width, int height, int finer) {
  std::vector<float> averaged(std::size_t(width) * std::size_t(height), 0.0f);
  const std::size_t finerWidth = std::size_t(width) * finer;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::size_t x = i % finerWidth / finer, y = i / finerWidth / finer;
    averaged[y * width + x] += values[i];
  }
  for (float& value : averaged) value /= float(finer * finer);
  return averaged;
}

// GDAL reduces a band in its own type, so averages of integers round (a 0/1 mask's edge becomes 0 or 1),
// and a nodata mask to "any texel valid" (a 0/255 step). Either would turn the edge of a coarse level into a
// step, and a feather (composite.overlay_mask), which averages coverage over those levels, into a hard edge.
// So a reduced read of such a band that holds an edge is read again kFiner times finer and averaged here:
// edges then lie within 1/kFiner of a texel of the level. 4: that, at 16 times the read, on edge pages only.
constexpr int kFiner = 4;

std::vector<float> readBand(GDALRasterBand& band, const RasterWindow& window, int width, int height, bool refineEdges) {
  std::vector<float> values = readReduced(band, window, width, height);
  const int finer = std::min({kFiner, window.width / width, window.height / height});
  if (!refineEdges || finer < 2 || !holdsAnEdge(values)) return values;
  return boxAveraged(readReduced(band, window, width * finer, height * finer), width, height, finer);
}

// Coverage per texel in [0, 1] from the mask band of `band` (0 or 255, averaged where reduced).
std::vector<float> readCoverage(GDALRasterBand& band, const RasterWindow& window, int width, int height) {
  std::vector<float> coverage = readBand(*band.GetMaskBand(), window, width, height, true);
  for (float& c : coverage) c /= 255.0f;
  return coverage;
}

template <typename Texel>
void store(std::span<std::byte> texels, std::size_t i, const Texel& texel) {
  std::memcpy(texels.data() + i * sizeof(Texel), &texel, sizeof(Texel));
}

// PageFormat::Colour: half-float r, g, b as encoded, scaled to [0, 1] and premultiplied by coverage, then
// coverage. Reduced levels are GDAL's averages of the encoded values (gamma-space mip levels).
void readColour(GDALDataset& dataset, const RasterWindow& window, int width, int height, std::span<std::byte> texels) {
  const int bands = dataset.GetRasterCount();
  GDALRasterBand& first = *dataset.GetRasterBand(1);
  const float full = first.GetRasterDataType() == GDT_Byte ? 255.0f : 65535.0f;
  std::array<std::vector<float>, 3> rgb;
  for (int c = 0; c < 3; ++c)
    rgb[c] = readBand(*dataset.GetRasterBand(bands >= 3 ? c + 1 : 1), window, width, height, false);
  const std::vector<float> coverage = readCoverage(first, window, width, height);
  for (std::size_t i = 0; i < coverage.size(); ++i) {
    std::array<std::uint16_t, 4> texel{};
    for (int c = 0; c < 3; ++c) texel[c] = glm::packHalf1x16(rgb[c][i] / full * coverage[i]);
    texel[3] = glm::packHalf1x16(coverage[i]);
    store(texels, i, texel);
  }
}

// The values of a mask, whose edges are feathered, are refined at edges as coverage is (readBand), where GDAL
// rounds them (integer bands: 0/1 masks) and nothing is masked (a masked texel read finer would bring the
// nodata value into the average).
bool refinesValues(GDALRasterBand& band, LayerKind kind) {
  return kind == LayerKind::Mask && !GDALDataTypeIsFloating(band.GetRasterDataType()) &&
         band.GetMaskFlags() == GMF_ALL_VALID;
}

// PageFormat::Values: value x coverage, coverage, as 32-bit floats.
void readValues(GDALDataset& dataset, LayerKind kind, const RasterWindow& window, int width, int height,
                std::span<std::byte> texels) {
  GDALRasterBand& band = *dataset.GetRasterBand(1);
  const std::vector<float> values = readBand(band, window, width, height, refinesValues(band, kind));
  const std::vector<float> coverage = readCoverage(band, window, width, height);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float c = std::isfinite(values[i]) ? coverage[i] : 0.0f;
    store(texels, i, std::array<float, 2>{c > 0.0f ? values[i] * c : 0.0f, c});
  }
}

void checkColourBands(GDALDataset& dataset, const SourceLocation& where) {
  const GDALDataType type = dataset.GetRasterBand(1)->GetRasterDataType();
  if (type != GDT_Byte && type != GDT_UInt16)
    throw Error(where,
                "'" + std::string(dataset.GetDescription()) + "' holds " + GDALGetDataTypeName(type) +
                    " values, but a colour layer needs 8 or 16-bit bands",
                "use `kind: scalar` for measurements, or convert: gdal_translate -ot Byte -scale");
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
              "'" + file + "' band " + std::to_string(band.GetBand()) + " declares nodata " + value.data() +
                  ", which no " + GDALGetDataTypeName(type) + " sample can hold, so it would mask nothing",
              "set the value the file really uses: gdal_edit.py -a_nodata VALUE " + file +
                  ", or remove it: gdal_edit.py -unsetnodata " + file);
}

}  // namespace

PageFormat pageFormatOf(LayerKind kind) {
  return kind == LayerKind::Color || kind == LayerKind::Normal ? PageFormat::Colour : PageFormat::Values;
}

void checkRaster(GDALDataset& dataset, LayerKind kind, const SourceLocation& where) {
  if (dataset.GetRasterCount() < 1 || dataset.GetRasterXSize() < 1 || dataset.GetRasterYSize() < 1)
    throw Error(where, "'" + std::string(dataset.GetDescription()) + "' has no raster data",
                "point `path` at a raster (gdalinfo FILE lists its bands)");
  for (int band = 1; band <= dataset.GetRasterCount(); ++band) checkNodata(*dataset.GetRasterBand(band), where);
  if (pageFormatOf(kind) == PageFormat::Colour) checkColourBands(dataset, where);
  checkPageableSize(dataset, where);
}

void readWindow(GDALDataset& dataset, LayerKind kind, const RasterWindow& window, int width, int height,
                std::span<std::byte> texels) {
  if (pageFormatOf(kind) == PageFormat::Colour)
    readColour(dataset, window, width, height, texels);
  else
    readValues(dataset, kind, window, width, height, texels);
}

}  // namespace strata::gdal
