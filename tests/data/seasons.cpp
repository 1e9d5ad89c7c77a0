#include "seasons.hpp"

#include <gdal_priv.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::testdata {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::array<double, 3> kSnow{240.0, 242.0, 250.0};

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

// How much snow covers latitude `lat` (deg) in month `month` (1 to 12): 1 poleward of the snow line, 0
// equatorward, over a 4 degree ramp. The northern line is furthest south in January, the southern in July.
double snowCover(double lat, int month) {
  const double swing = 22.5 * std::cos(2.0 * kPi * (month - 1) / 12.0);
  const double line = lat >= 0.0 ? 62.5 - swing : 62.5 + swing;
  return std::clamp((std::abs(lat) - line) / 4.0 + 0.5, 0.0, 1.0);
}

void writeMonth(GDALDataset& like, const std::vector<unsigned char>& rgba, int width, int height, int month,
                const std::filesystem::path& file) {
  std::vector<unsigned char> out(rgba);
  for (int row = 0; row < height; ++row) {
    const double cover = snowCover(90.0 - 180.0 * (row + 0.5) / height, month);
    for (std::size_t i = std::size_t(row) * width; i < std::size_t(row + 1) * width; ++i)
      for (std::size_t c = 0; c < 3; ++c)
        out[i * 4 + c] = (unsigned char)std::lround(rgba[i * 4 + c] + (kSnow[c] - rgba[i * 4 + c]) * cover);
  }
  Dataset memory(GetGDALDriverManager()->GetDriverByName("MEM")->Create("", width, height, 4, GDT_Byte, nullptr));
  std::array<double, 6> transform{};
  like.GetGeoTransform(transform.data());
  transform[1] *= double(like.GetRasterXSize()) / width;
  transform[5] *= double(like.GetRasterYSize()) / height;
  memory->SetGeoTransform(transform.data());
  memory->SetSpatialRef(like.GetSpatialRef());
  memory->GetRasterBand(4)->SetColorInterpretation(GCI_AlphaBand);
  if (memory->RasterIO(GF_Write, 0, 0, width, height, out.data(), width, height, GDT_Byte, 4, nullptr, 4,
                       std::int64_t(width) * 4, 1) != CE_None)
    throw std::runtime_error("cannot fill the month for " + file.string());
  const char* options[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=2", "ALPHA=YES", nullptr};
  Dataset written(GetGDALDriverManager()->GetDriverByName("GTiff")->CreateCopy(
      file.c_str(), memory.get(), false, const_cast<char**>(options), nullptr, nullptr));
  if (!written) throw std::runtime_error("GDAL cannot write '" + file.string() + "': " + CPLGetLastErrorMsg());
}

}  // namespace

void writeSeasons(const std::filesystem::path& directory) {
  const std::filesystem::path global = directory / "global-color.tif";
  Dataset source(GDALDataset::Open(global.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!source || source->GetRasterCount() != 4) throw std::runtime_error("cannot read RGBA '" + global.string() + "'");
  const int width = source->GetRasterXSize() / 2, height = source->GetRasterYSize() / 2;
  std::vector<unsigned char> rgba(std::size_t(width) * height * 4);
  if (source->RasterIO(GF_Read, 0, 0, source->GetRasterXSize(), source->GetRasterYSize(), rgba.data(), width, height,
                       GDT_Byte, 4, nullptr, 4, std::int64_t(width) * 4, 1) != CE_None)
    throw std::runtime_error("cannot read '" + global.string() + "'");
  for (int month = 1; month <= 12; ++month) {
    char name[48];  // room for any int, as GCC checks under -O1
    std::snprintf(name, sizeof name, "season-2004%02d-color.tif", month);
    writeMonth(*source, rgba, width, height, month, directory / name);
  }
}

}  // namespace strata::testdata
