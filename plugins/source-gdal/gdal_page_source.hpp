#pragma once
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <gdal_priv.h>

#include <strata/plugin/page_source.hpp>
#include <strata/plugin/port.hpp>

#include "colour_encoding.hpp"
#include "memory_file.hpp"

namespace strata::gdal {

// The pages of a raster file, read with GDAL on the page cache's loader threads: level l is read as
// windows of the raster averaged down by 2^l, which GDAL serves from the file's overview of that
// resolution when it has one (a COG from `strata tile` has all of them). Colours are read as they are
// encoded, in `encoding`'s colour space, which the page cache converts on the GPU.
class GdalPageSource : public PageSource {
 public:
  // `dataset` was opened and checked (checkRaster); it serves the first read. `encoding`: that of a colour
  // raster whose values are not scene-linear. `memoryFile`: the in-memory file it was opened from, if any
  // (a rasterised polygon mask), kept while the source reads it.
  GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind, std::optional<ColourEncoding> encoding,
                 std::shared_ptr<const MemoryFile> memoryFile = nullptr);
  // The same, paged as `pyramid` says (a pyramid of the raster's size that may stop early).
  GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind, std::optional<ColourEncoding> encoding,
                 PagePyramid pyramid);
  ~GdalPageSource() override;

  const PagePyramid& pyramid() const override { return pyramid_; }
  PageFormat format() const override;
  std::string name() const override { return path_; }
  void read(const LevelWindow& window, std::span<std::byte> texels) const override;
  std::string toSceneLinearGlsl(const std::string& functionName) const override;

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
  std::optional<ColourEncoding> encoding_;
  PagePyramid pyramid_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<GDALDataset>> idle_;
};

}  // namespace strata::gdal
