#pragma once
// What every layout `strata tile` writes shares: the Cloud Optimized GeoTIFF the page cache reads, written
// through GDAL's COG driver, and GDAL's utilities run on every core.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gdal_priv.h>

#include <strata/error.hpp>

namespace strata::tiling {

using Dataset = std::unique_ptr<GDALDataset>;

// While it lives, GDAL's warper on this thread uses every core (GDAL_NUM_THREADS=ALL_CPUS).
class AllCpusForWarping {
 public:
  AllCpusForWarping();
  ~AllCpusForWarping();
  AllCpusForWarping(const AllCpusForWarping&) = delete;
  AllCpusForWarping& operator=(const AllCpusForWarping&) = delete;

 private:
  std::string previous_;
};

// The argv that GDAL's utility options parsers take, pointing into `arguments`, ending with a null.
std::vector<char*> argvOf(std::vector<std::string>& arguments);

// GDAL's progress callback for a std::function<void(double)> passed as its data.
int reportProgress(double fraction, const char* message, void* progress);

// Copies `source` to `output` as a COG: 512x512 tiles, averaged overviews, lossless compression, reprojected
// with GDAL's warper (bilinear) into `targetCrs` unless it is empty. Throws strata::Error at `where`.
Dataset writeCog(GDALDataset& source, const std::filesystem::path& output, const std::string& targetCrs,
                 std::function<void(double)> progress, const SourceLocation& where);

}  // namespace strata::tiling
