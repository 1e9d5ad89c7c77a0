#pragma once
// What every layout `strata tile` writes shares: the Cloud Optimized GeoTIFF the page cache reads, written
// through GDAL's COG driver, and GDAL's utilities run on every core.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
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

// A part of a longer task's `progress`: fractions of the part go to the whole's [from, to]; empty where
// `progress` is.
std::function<void(double)> progressShare(const std::function<void(double)>& progress, double from, double to);

// GDAL's progress callback for a std::function<void(double)> passed as its data.
int reportProgress(double fraction, const char* message, void* progress);

// Name and value of items of a file's metadata (GDAL's default domain).
using MetadataItems = std::vector<std::pair<std::string, std::string>>;

// Copies `source` to `output` as a COG: 512x512 tiles, averaged overviews, lossless compression, reprojected
// with GDAL's warper (bilinear) into `targetCrs` unless it is empty, with `metadata` added to the source's.
// Throws strata::Error at `where`.
Dataset writeCog(GDALDataset& source, const std::filesystem::path& output, const std::string& targetCrs,
                 std::function<void(double)> progress, const SourceLocation& where, const MetadataItems& metadata = {});

}  // namespace strata::tiling
