#include "ice_sheet.hpp"

#include <gdal_priv.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "observation_writer.hpp"

namespace strata::testdata {
namespace {

constexpr double kPoleThickness = 3000.0;  // m: Greenland's ice is some 3 km thick at its summit
constexpr double kSheetRadius = 1.2e6;     // m from the pole, in the cap's projected metres

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

// Vialov's profile of an ice sheet on a flat bed: H0 (1 - (r / L)^(4/3))^(3/8), 0 beyond L.
double thickness(double x, double y) {
  const double r = std::hypot(x, y) / kSheetRadius;
  return r < 1.0 ? kPoleThickness * std::pow(1.0 - std::pow(r, 4.0 / 3.0), 3.0 / 8.0) : 0.0;
}

Dataset create(GDALDataset& like, const std::filesystem::path& file, int bands, GDALDataType type) {
  const char* options[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=2", bands == 4 ? "ALPHA=YES" : nullptr, nullptr};
  Dataset written(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      file.c_str(), like.GetRasterXSize(), like.GetRasterYSize(), bands, type, const_cast<char**>(options)));
  if (!written) throw std::runtime_error("GDAL cannot write '" + file.string() + "': " + CPLGetLastErrorMsg());
  std::array<double, 6> transform{};
  like.GetGeoTransform(transform.data());
  written->SetGeoTransform(transform.data());
  written->SetSpatialRef(like.GetSpatialRef());
  return written;
}

void write(GDALDataset& dataset, int bands, GDALDataType type, void* data, const std::filesystem::path& file) {
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  const int bytes = GDALGetDataTypeSizeBytes(type);
  if (dataset.RasterIO(GF_Write, 0, 0, width, height, data, width, height, type, bands, nullptr, bytes * bands,
                       std::int64_t(width) * bytes * bands, bytes) != CE_None)
    throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace

void writeIceSheet(const std::filesystem::path& directory) {
  const std::filesystem::path bedrockFile = directory / "north-height.tif";
  Dataset bedrock(GDALDataset::Open(bedrockFile.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!bedrock) throw std::runtime_error("cannot read '" + bedrockFile.string() + "'");
  const int width = bedrock->GetRasterXSize(), height = bedrock->GetRasterYSize();
  std::vector<float> surface(std::size_t(width) * height);
  if (bedrock->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width, height, surface.data(), width, height, GDT_Float32, 0,
                                          0) != CE_None)
    throw std::runtime_error("cannot read '" + bedrockFile.string() + "'");
  std::array<double, 6> t{};
  bedrock->GetGeoTransform(t.data());
  std::vector<unsigned char> colour(surface.size() * 4);
  for (std::size_t i = 0; i < surface.size(); ++i) {
    const double ice = thickness(t[0] + (double(i % width) + 0.5) * t[1], t[3] + (double(i / width) + 0.5) * t[5]);
    const bool covered = ice > 0.0 && surface[i] != float(kHeightNodata);
    surface[i] = covered ? float(surface[i] + ice) : float(kHeightNodata);
    const double pale = ice / kPoleThickness;
    const std::array<double, 4> rgba{190 + 55 * pale, 215 + 35 * pale, 240 + 10 * pale, covered ? 255.0 : 0.0};
    for (std::size_t c = 0; c < 4; ++c) colour[i * 4 + c] = (unsigned char)std::lround(rgba[c]);
  }
  const std::filesystem::path heightFile = directory / "ice-height.tif", colourFile = directory / "ice-color.tif";
  Dataset heights = create(*bedrock, heightFile, 1, GDT_Float32);
  heights->GetRasterBand(1)->SetNoDataValue(kHeightNodata);
  write(*heights, 1, GDT_Float32, surface.data(), heightFile);
  Dataset colours = create(*bedrock, colourFile, 4, GDT_Byte);
  colours->GetRasterBand(4)->SetColorInterpretation(GCI_AlphaBand);
  write(*colours, 4, GDT_Byte, colour.data(), colourFile);
}

}  // namespace strata::testdata
