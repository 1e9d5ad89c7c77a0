#include "panchromatic.hpp"

#include <gdal_priv.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::testdata {
namespace {

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

constexpr float kNodata = -1.0f;

// Scene-linear light of each 8-bit sRGB level (IEC 61966-2-1).
std::array<double, 256> linearLevels() {
  std::array<double, 256> linear{};
  for (std::size_t i = 0; i < linear.size(); ++i) {
    const double e = double(i) / 255.0;
    linear[i] = e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
  }
  return linear;
}

// Relative luminance (Rec. 709 weights, IEC 61966-2-1's Y row) of RGBA texels, kNodata where alpha is 0.
std::vector<float> luminanceOf(const std::vector<unsigned char>& rgba) {
  const std::array<double, 256> linear = linearLevels();
  std::vector<float> luminance(rgba.size() / 4);
  for (std::size_t i = 0; i < luminance.size(); ++i) {
    const unsigned char* t = &rgba[i * 4];
    luminance[i] = t[3] == 0 ? kNodata
                             : float(kPanchromaticGain *
                                     (0.2126729 * linear[t[0]] + 0.7151522 * linear[t[1]] + 0.0721750 * linear[t[2]]));
  }
  return luminance;
}

}  // namespace

void writePanchromatic(const std::filesystem::path& directory) {
  const std::filesystem::path strip = directory / "strip-color.tif", file = directory / "strip-luminance.tif";
  Dataset source(GDALDataset::Open(strip.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!source || source->GetRasterCount() != 4) throw std::runtime_error("cannot read RGBA '" + strip.string() + "'");
  const int width = source->GetRasterXSize(), height = source->GetRasterYSize();
  std::vector<unsigned char> rgba(std::size_t(width) * height * 4);
  if (source->RasterIO(GF_Read, 0, 0, width, height, rgba.data(), width, height, GDT_Byte, 4, nullptr, 4,
                       std::int64_t(width) * 4, 1) != CE_None)
    throw std::runtime_error("cannot read '" + strip.string() + "'");
  const char* options[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=3", nullptr};
  Dataset written(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(file.c_str(), width, height, 1, GDT_Float32,
                                                                           const_cast<char**>(options)));
  if (!written) throw std::runtime_error("GDAL cannot create '" + file.string() + "': " + CPLGetLastErrorMsg());
  std::array<double, 6> transform{};
  source->GetGeoTransform(transform.data());
  written->SetGeoTransform(transform.data());
  written->SetSpatialRef(source->GetSpatialRef());
  GDALRasterBand& band = *written->GetRasterBand(1);
  band.SetNoDataValue(kNodata);
  std::vector<float> luminance = luminanceOf(rgba);
  if (band.RasterIO(GF_Write, 0, 0, width, height, luminance.data(), width, height, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error("cannot write '" + file.string() + "': " + CPLGetLastErrorMsg());
}

}  // namespace strata::testdata
