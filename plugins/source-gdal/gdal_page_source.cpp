#include "gdal_page_source.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "quiet_gdal_errors.hpp"
#include "raster_reading.hpp"

namespace strata::gdal {

GdalPageSource::GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind,
                               std::optional<ColourEncoding> encoding, std::shared_ptr<const MemoryFile> memoryFile)
    : memoryFile_(std::move(memoryFile)),
      path_(dataset->GetDescription()),
      kind_(kind),
      encoding_(std::move(encoding)),
      pyramid_(dataset->GetRasterXSize(), dataset->GetRasterYSize()) {
  idle_.push_back(std::move(dataset));
}

GdalPageSource::GdalPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind,
                               std::optional<ColourEncoding> encoding, PagePyramid pyramid)
    : path_(dataset->GetDescription()), kind_(kind), encoding_(std::move(encoding)), pyramid_(pyramid) {
  idle_.push_back(std::move(dataset));
}

GdalPageSource::~GdalPageSource() = default;

PageFormat GdalPageSource::format() const { return pageFormatOf(kind_); }

// A level texel covers 2^level raster texels; the raster's edge cuts the last row and column short,
// and GDAL spreads what remains over them (under one level texel of shift, at the far edges only).
void GdalPageSource::read(const LevelWindow& window, std::span<std::byte> texels) const {
  const std::int64_t scale = std::int64_t{1} << window.level;  // in 64 bits: a page of level 22 spans 2^31 texels
  const int x = int(window.x * scale), y = int(window.y * scale);
  const RasterWindow raster{x, y, int(std::min(window.width * scale, std::int64_t{pyramid_.width()} - x)),
                            int(std::min(window.height * scale, std::int64_t{pyramid_.height()} - y))};
  Borrowed dataset(*this);
  const RecordedGdalErrors recorded;
  readWindow(*dataset.handle, kind_, raster, window.width, window.height, texels);
  if (!recorded.first()) return;
  // Damaged data decoded with a warning: the dataset's block cache now holds what was decoded, which a
  // second read would return without the warning, so the dataset is closed rather than given back.
  dataset.handle.reset();
  throw std::runtime_error(*recorded.first());
}

std::string GdalPageSource::toSceneLinearGlsl(const std::string& functionName) const {
  return encoding_ ? encoding_->toSceneLinearGlsl(functionName) : std::string();
}

GdalPageSource::Borrowed::Borrowed(const GdalPageSource& source) : owner(source), handle(source.borrow()) {}

GdalPageSource::Borrowed::~Borrowed() {
  if (handle) owner.giveBack(std::move(handle));
}

std::unique_ptr<GDALDataset> GdalPageSource::borrow() const {
  {
    std::scoped_lock lock(mutex_);
    if (!idle_.empty()) {
      std::unique_ptr<GDALDataset> dataset = std::move(idle_.back());
      idle_.pop_back();
      return dataset;
    }
  }
  CPLErrorReset();
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(path_.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset) throw std::runtime_error("'" + path_ + "' can no longer be opened: " + CPLGetLastErrorMsg());
  return dataset;
}

void GdalPageSource::giveBack(std::unique_ptr<GDALDataset> dataset) const {
  std::scoped_lock lock(mutex_);
  idle_.push_back(std::move(dataset));
}

}  // namespace strata::gdal
