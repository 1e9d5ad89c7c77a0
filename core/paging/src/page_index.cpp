#include "page_index.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace strata::paging {
namespace {

constexpr std::uint32_t kLoaded = 0x80000000u;

std::uint32_t reference(int level, int slot) { return kLoaded | (std::uint32_t(level) << 16) | std::uint32_t(slot); }

// The index is one texture of kIndexWidth entries a row, as many rows as the GL allows, addressed by
// 32-bit offsets.
std::size_t mostEntries() {
  GLint rows = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &rows);
  return std::min<std::size_t>(std::size_t(rows) * PageIndex::kIndexWidth, 0xFFFFFFFFu);
}

std::size_t entriesOf(const PagePyramid& pyramid) {
  std::size_t entries = std::size_t(pyramid.levels());
  for (int level = 0; level < pyramid.levels(); ++level) entries += pyramid.pageCount(level);
  return entries;
}

}  // namespace

PageIndex::~PageIndex() {
  if (texture_) glDeleteTextures(1, &texture_);
}

unsigned PageIndex::add(const PagePyramid& pyramid) {
  const std::size_t most = mostEntries();
  if (entriesOf(pyramid) > most - std::min(most, entries_.size()))
    throw std::length_error("a raster of " + std::to_string(pyramid.width()) + "x" + std::to_string(pyramid.height()) +
                            " texels has " + std::to_string(entriesOf(pyramid)) +
                            " pages in all, more than the page index holds with the layers before it (" +
                            std::to_string(most) + " on this GL); make a coarser copy: gdal_translate -outsize");
  const auto base = unsigned(entries_.size());
  std::size_t next = base + std::size_t(pyramid.levels());
  entries_.resize(next);
  for (int level = 0; level < pyramid.levels(); ++level) {
    entries_[base + std::size_t(level)] = std::uint32_t(next);
    next += pyramid.pageCount(level);
  }
  entries_.resize(next, 0u);
  slots_.resize(next, -1);
  layers_.push_back({pyramid, base});
  return base;
}

void PageIndex::allocate() {
  const int rows = int((entries_.size() + kIndexWidth - 1) / kIndexWidth);
  entries_.resize(std::size_t(rows) * kIndexWidth, 0u);
  glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
  glTextureStorage2D(texture_, 1, GL_R32UI, kIndexWidth, rows);
  // Integer textures are incomplete, and read as zero, under the default mipmapped filter.
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  dirtyBegin_ = 0;
  dirtyEnd_ = entries_.size();
  upload();
}

std::size_t PageIndex::entryOf(const Layer& layer, const PageKey& key) const {
  return entries_[layer.base + std::size_t(key.level)] +
         std::size_t(key.row) * std::size_t(layer.pyramid.pagesAcross(key.level)) + std::size_t(key.column);
}

// The page's own slot when loaded, else what its parent references (its nearest loaded ancestor).
std::uint32_t PageIndex::referenceFor(const Layer& layer, const PageKey& key) const {
  const std::int32_t own = slots_[entryOf(layer, key)];
  if (own >= 0) return reference(key.level, own);
  if (key.level + 1 >= layer.pyramid.levels()) return 0u;
  return entries_[entryOf(layer, {key.level + 1, key.column / 2, key.row / 2})];
}

void PageIndex::place(int layerNumber, const PageKey& key, std::optional<int> slot) {
  const Layer& layer = layers_[std::size_t(layerNumber)];
  slots_[entryOf(layer, key)] = slot ? *slot : -1;
  // The page and every page under it, level by level downward, so each sees its parent's new entry.
  for (int level = key.level, span = 1; level >= 0; --level, span *= 2) {
    const int columnEnd = std::min((key.column + 1) * span, layer.pyramid.pagesAcross(level));
    const int rowEnd = std::min((key.row + 1) * span, layer.pyramid.pagesDown(level));
    for (int row = key.row * span; row < rowEnd; ++row)
      for (int column = key.column * span; column < columnEnd; ++column) {
        const PageKey page{level, column, row};
        const std::size_t entry = entryOf(layer, page);
        entries_[entry] = referenceFor(layer, page);
        dirtyBegin_ = dirtyBegin_ == dirtyEnd_ ? entry : std::min(dirtyBegin_, entry);
        dirtyEnd_ = std::max(dirtyEnd_, entry + 1);
      }
  }
}

void PageIndex::upload() {
  if (dirtyBegin_ >= dirtyEnd_ || !texture_) return;
  const int firstRow = int(dirtyBegin_ / kIndexWidth), lastRow = int((dirtyEnd_ - 1) / kIndexWidth);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture_, 0, 0, firstRow, kIndexWidth, lastRow - firstRow + 1, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      entries_.data() + std::size_t(firstRow) * kIndexWidth);
  dirtyBegin_ = dirtyEnd_ = 0;
}

}  // namespace strata::paging
