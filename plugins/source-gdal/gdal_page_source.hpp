#pragma once
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <gdal_priv.h>

#include <strata/page_source.hpp>
#include <strata/port.hpp>

#include "memory_file.hpp"

namespace strata::gdal {

// The pages of a raster file, read with GDAL on the page cache's loader threads: level l is read as
// windows of the raster averaged down by 2^l, which GDAL serves from the file's overview of that
// resolution when it has one (a COG from `strata tile` has all of them).
class GdalPageSource : public PageSource {
 public:
  // `dataset` was opened and checked (checkRaster); it serves the first read. `memoryFile`: the in-memory
  // file it was opened from, if any (a rasterised polygon mask), kept while the source reads it.
  GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind,
                 std::shared_ptr<const MemoryFile> memoryFile = nullptr);
  // The same, paged as `pyramid` says (a pyramid of the raster's size that may stop early).
  GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind, PagePyramid pyramid);
  ~GdalPageSource() override;

  const PagePyramid& pyramid() const override { return pyramid_; }
  PageFormat format() const override;
  std::string name() const override { return path_; }
  void read(const LevelWindow& window, std::span<std::byte> texels) const override;

 private:
  // GDAL datasets are not safe to share between threads: each read borrows one of its own.
  struct Borrowed {
    explicit Borrowed(const GdalPageSource& source);
    ~Borrowed();
    const GdalPageSource& owner;
    std::unique_ptr<GDALDataset> handle;
  };
  std::unique_ptr<GDALDataset> borrow() const;
  void giveBack(std::unique_ptr<GDALDataset> dataset) const;

  std::shared_ptr<const MemoryFile> memoryFile_;  // first, so that it goes after every dataset
  std::string path_;
  LayerKind kind_;
  PagePyramid pyramid_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<GDALDataset>> idle_;
};

}  // namespace strata::gdal
