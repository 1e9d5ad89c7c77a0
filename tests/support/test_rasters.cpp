#include "test_rasters.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <memory>
#include <stdexcept>

namespace strata::test {
namespace {

std::unique_ptr<GDALDataset> createGeoTiff(const std::filesystem::path& file, int width, int height, int bands,
                                           GDALDataType type, std::array<double, 4> extent) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  std::unique_ptr<GDALDataset> dataset(driver->Create(file.c_str(), width, height, bands, type, nullptr));
  if (!dataset) throw std::runtime_error("cannot create " + file.string());
  double transform[6] = {extent[0], (extent[2] - extent[0]) / width,  0, extent[3],
                         0,         -(extent[3] - extent[1]) / height};
  dataset->SetGeoTransform(transform);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  dataset->SetSpatialRef(&wgs84);
  return dataset;
}

template <typename Sample>
void writeRgb(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent, GDALDataType type,
              const std::function<std::array<Sample, 3>(int, int)>& colour) {
  auto dataset = createGeoTiff(file, width, height, 3, type, extent);
  std::vector<Sample> band(std::size_t(width) * height);
  for (int channel = 0; channel < 3; ++channel) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) band[std::size_t(y) * width + x] = colour(x, y)[std::size_t(channel)];
    if (dataset->GetRasterBand(channel + 1)
            ->RasterIO(GF_Write, 0, 0, width, height, band.data(), width, height, type, 0, 0) != CE_None)
      throw std::runtime_error("cannot write " + file.string());
  }
}

}  // namespace

Rgb8 cellColour(int column, int row) {
  return {static_cast<unsigned char>(20 + 30 * column), static_cast<unsigned char>(40 + 60 * row),
          static_cast<unsigned char>(230 - 24 * column - 5 * row)};
}

void writeCheckerboard(const std::filesystem::path& file) {
  constexpr int cell = 32;
  writeColourRaster(file, 256, 128, {-180, -90, 180, 90}, [](int x, int y) { return cellColour(x / cell, y / cell); });
}

void writeColourRaster(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                       const std::function<Rgb8(int column, int row)>& colour) {
  writeRgb<unsigned char>(file, width, height, extent, GDT_Byte, colour);
}

void writeColourRaster16(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                         const std::function<Rgb16(int column, int row)>& colour) {
  writeRgb<std::uint16_t>(file, width, height, extent, GDT_UInt16, colour);
}

void writeFloatRaster(const std::filesystem::path& file, int width, int height, std::array<double, 4> extent,
                      const std::function<float(int, int)>& value, std::optional<double> nodata) {
  auto dataset = createGeoTiff(file, width, height, 1, GDT_Float32, extent);
  std::vector<float> band(width * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) band[y * width + x] = value(x, y);
  GDALRasterBand* raster = dataset->GetRasterBand(1);
  if (nodata) raster->SetNoDataValue(*nodata);
  if (raster->RasterIO(GF_Write, 0, 0, width, height, band.data(), width, height, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error("cannot write " + file.string());
}

double rasterFileValue(int column, int row, int band) { return (column * 7 + row * 13 + band * 101) % 251; }

void writeRasterFile(const std::filesystem::path& file, const RasterFileSpec& spec) {
  GDALAllRegister();
  std::vector<const char*> options;
  for (const std::string& option : spec.creationOptions) options.push_back(option.c_str());
  options.push_back(nullptr);
  std::unique_ptr<GDALDataset> dataset(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      file.c_str(), spec.width, spec.height, spec.bands, spec.type, const_cast<char**>(options.data())));
  OGRSpatialReference crs;
  if (!dataset || crs.SetFromUserInput(spec.crs.c_str()) != OGRERR_NONE)
    throw std::runtime_error("cannot create " + file.string() + " in " + spec.crs);
  dataset->SetSpatialRef(&crs);
  std::array<double, 6> geotransform = spec.geotransform;
  dataset->SetGeoTransform(geotransform.data());
  std::vector<double> row(static_cast<std::size_t>(spec.width));
  for (int band = 1; band <= spec.bands; ++band) {
    GDALRasterBand* raster = dataset->GetRasterBand(band);
    if (spec.nodata) raster->SetNoDataValue(*spec.nodata);
    for (int y = 0; y < spec.height && spec.values; ++y) {
      for (int x = 0; x < spec.width; ++x) row[static_cast<std::size_t>(x)] = rasterFileValue(x, y, band);
      if (raster->RasterIO(GF_Write, 0, y, spec.width, 1, row.data(), spec.width, 1, GDT_Float64, 0, 0) != CE_None)
        throw std::runtime_error("cannot write " + file.string());
    }
  }
}

std::array<int, 4> Image::at(int x, int y) const {
  const unsigned char* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

Image readImage(const std::filesystem::path& file) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset) throw std::runtime_error("cannot open " + file.string());
  Image image{dataset->GetRasterXSize(), dataset->GetRasterYSize(), {}};
  image.rgba.assign(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  const int bands = std::min(dataset->GetRasterCount(), 4);
  for (int band = 1; band <= bands; ++band)
    if (dataset->GetRasterBand(band)->RasterIO(GF_Read, 0, 0, image.width, image.height, &image.rgba[band - 1],
                                               image.width, image.height, GDT_Byte, 4, image.width * 4) != CE_None)
      throw std::runtime_error("cannot read " + file.string());
  return image;
}

}  // namespace strata::test
