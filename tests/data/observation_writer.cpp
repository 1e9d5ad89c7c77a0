#include "observation_writer.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "pixel_positions.hpp"
#include "srgb_encoding.hpp"

namespace strata::testdata {
namespace {

// GeoTIFF tiles of 256 x 256; a block of rows is one row of tiles, so each write completes its tiles.
constexpr int kTileSize = 256;

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

Dataset createRaster(const std::filesystem::path& file, const Observation& observation, GDALDataType type, int bands) {
  const bool colour = type == GDT_Byte;
  CPLStringList options;
  options.SetNameValue("TILED", "YES");
  options.SetNameValue("BLOCKXSIZE", std::to_string(kTileSize).c_str());
  options.SetNameValue("BLOCKYSIZE", std::to_string(kTileSize).c_str());
  options.SetNameValue("COMPRESS", "DEFLATE");
  options.SetNameValue("PREDICTOR", colour ? "2" : "3");  // horizontal differencing: integer, floating point
  options.SetNameValue("BIGTIFF", "IF_SAFER");            // --large colour rasters pass 4 GiB
  options.SetNameValue("NUM_THREADS", "ALL_CPUS");        // compression overlaps the planet's evaluation
  if (colour) {
    options.SetNameValue("PHOTOMETRIC", "RGB");
    options.SetNameValue("ALPHA", "YES");  // unassociated: colours are not premultiplied
  }
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  Dataset dataset(driver->Create(file.c_str(), observation.width, observation.height, bands, type, options.List()));
  if (!dataset) throw std::runtime_error("GDAL cannot create '" + file.string() + "': " + CPLGetLastErrorMsg());
  double northUp[6] = {observation.west, observation.pixelWidth, 0.0, observation.north, 0.0, -observation.pixelHeight};
  OGRSpatialReference crs;
  if (dataset->SetGeoTransform(northUp) != CE_None || crs.importFromProj4(observation.crs.c_str()) != OGRERR_NONE ||
      dataset->SetSpatialRef(&crs) != CE_None)
    throw std::runtime_error("GDAL cannot georeference '" + file.string() + "' as " + observation.crs);
  dataset->SetMetadataItem(kFootprintItem, CPLSPrintf("%.17g", observation.footprint));  // every digit of the double
  if (!colour) dataset->GetRasterBand(1)->SetNoDataValue(kHeightNodata);
  return dataset;
}

// One block of rows: heights, and colours as interleaved 8-bit sRGB plus alpha.
struct Block {
  int firstRow = 0;
  int rows = 0;
  std::vector<float> heights;
  std::vector<std::uint8_t> colours;
};

void computeBlock(const Observation& observation, const procedural::PlanetModel& planet, PixelPositions& positions,
                  bool withHeights, Block& block) {
  const auto width = std::size_t(observation.width);
  block.heights.assign(withHeights ? width * block.rows : 0, float(kHeightNodata));
  block.colours.assign(width * block.rows * 4, 0);
  for (int r = 0; r < block.rows; ++r) {
    const std::vector<glm::dvec2>& lonlat = positions.row(block.firstRow + r);
    for (std::size_t i = 0; i < width; ++i) {
      const double lon = lonlat[i].x, lat = lonlat[i].y;
      if (std::isnan(lon) || !observation.covers(lon, lat)) continue;
      const glm::dvec3 normal(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      const double height = planet.height(normal, observation.footprint);
      const std::size_t pixel = std::size_t(r) * width + i;
      if (withHeights) block.heights[pixel] = float(height);
      const std::array<std::uint8_t, 3> rgb = procedural::encodeSrgb8(planet.colour(height));
      std::copy(rgb.begin(), rgb.end(), &block.colours[pixel * 4]);
      block.colours[pixel * 4 + 3] = 255;
    }
  }
}

// Writes a block and flushes it: its tiles are complete, and GDAL's block cache would otherwise keep up
// to 5% of the machine's memory of them.
void writeBlock(const Block& block, int width, GDALDataset* heights, GDALDataset& colours) {
  CPLErr result =
      colours.RasterIO(GF_Write, 0, block.firstRow, width, block.rows, const_cast<std::uint8_t*>(block.colours.data()),
                       width, block.rows, GDT_Byte, 4, nullptr, 4, GSpacing(4) * width, 1, nullptr);
  if (heights && result == CE_None)
    result = heights->GetRasterBand(1)->RasterIO(GF_Write, 0, block.firstRow, width, block.rows,
                                                 const_cast<float*>(block.heights.data()), width, block.rows,
                                                 GDT_Float32, 0, 0, nullptr);
  if (result != CE_None) throw std::runtime_error(std::string("GDAL cannot write: ") + CPLGetLastErrorMsg());
  colours.FlushCache();
  if (heights) heights->FlushCache();
}

}  // namespace

void writeObservation(const Observation& observation, const procedural::PlanetModel& planet,
                      const std::filesystem::path& directory, Products products, bool progress) {
  const std::filesystem::path stem = directory / observation.name;
  Dataset heights = products == Products::HeightAndColour
                        ? createRaster(stem.string() + "-height.tif", observation, GDT_Float32, 1)
                        : nullptr;
  Dataset colours = createRaster(stem.string() + "-color.tif", observation, GDT_Byte, 4);
  const int blocks = (observation.height + kTileSize - 1) / kTileSize;
  std::atomic<int> nextBlock = 0;
  int blocksWritten = 0;
  std::mutex writing;  // GDAL datasets are not to be used by two threads at once
  std::exception_ptr failure;
  std::atomic<bool> failed = false;
  auto work = [&] {
    try {
      PixelPositions positions(observation);
      Block block;
      for (int b = nextBlock++; b < blocks && !failed; b = nextBlock++) {
        block.firstRow = b * kTileSize;
        block.rows = std::min(kTileSize, observation.height - block.firstRow);
        computeBlock(observation, planet, positions, heights != nullptr, block);
        const std::scoped_lock lock(writing);
        writeBlock(block, observation.width, heights.get(), *colours);
        ++blocksWritten;
        if (progress) {
          std::printf("\r%s: %3d%%", observation.name.c_str(), 100 * blocksWritten / blocks);
          std::fflush(stdout);
        }
      }
    } catch (...) {
      const std::scoped_lock lock(writing);
      failure = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::jthread> workers(std::max(1u, std::thread::hardware_concurrency()));
  for (std::jthread& worker : workers) worker = std::jthread(work);
  workers.clear();  // joins
  if (progress) std::printf("\n");
  if (failure) std::rethrow_exception(failure);
}

}  // namespace strata::testdata
