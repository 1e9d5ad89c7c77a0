// The true value ranges of a HEALPix pyramid's pages (strata/plugin/healpix_pyramid.hpp, PageRanges).
#include <strata/plugin/healpix_pyramid.hpp>

#include <algorithm>
#include <bit>
#include <limits>

#include "foundation/metadata_words.hpp"

namespace strata::healpix {
namespace {

using Range = PageRanges::Range;
using Level = std::vector<Range>;

constexpr const char* kItemPrefix = "STRATA_HEALPIX_RANGES_LEVEL_";

Range unite(const Range& a, const Range& b) {
  return {std::min(a.least, b.least), std::max(a.greatest, b.greatest), a.uncovered || b.uncovered};
}

constexpr Range kNothing{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), false};

// Pages a face side at pyramid level `level`.
std::int64_t pagesAcross(std::int64_t nside, int level) { return nside / kPagePayload >> level; }

// Each page of the next coarser level: its four children's ranges together.
Level coarser(const Level& finer, std::int64_t finerSide) {
  const std::int64_t side = finerSide / 2, width = 12 * side;
  Level level(std::size_t(width * side), kNothing);
  for (std::int64_t row = 0; row < finerSide; ++row)
    for (std::int64_t column = 0; column < 12 * finerSide; ++column) {
      Range& parent = level[std::size_t(row / 2 * width + column / 2)];
      parent = unite(parent, finer[std::size_t(row * 12 * finerSide + column)]);
    }
  return level;
}

// Each page's range with its eight neighbours', found on the sphere (texelAcross, pages for texels) where
// they lie beyond its face.
Level widened(const Level& level, std::int64_t side) {
  const std::int64_t width = 12 * side;
  Level wide(level.size());
  for (std::int64_t row = 0; row < side; ++row)
    for (std::int64_t column = 0; column < width; ++column) {
      const int face = int(column / side);
      Range range = kNothing;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          glm::ivec2 page(int(column) + dx, int(row) + dy);
          const std::int64_t local = page.x - face * side;
          if (local < 0 || local >= side || page.y < 0 || page.y >= side) page = texelAcross(int(side), face, page);
          range = unite(range, level[std::size_t(page.y * width + page.x)]);
        }
      wide[std::size_t(row * width + column)] = range;
    }
  return wide;
}

std::string encoded(const Level& level) {
  std::vector<std::uint32_t> words;
  words.reserve(level.size() * 3);
  for (const Range& range : level)
    for (const float value : {range.least, range.greatest, range.uncovered ? 1.0f : 0.0f})
      words.push_back(std::bit_cast<std::uint32_t>(value));
  return base64OfWords(words);
}

std::optional<Level> decoded(const char* text, std::size_t pages) {
  const std::optional<std::vector<std::uint32_t>> words = wordsOfBase64(text, pages * 3);
  if (!words) return std::nullopt;
  const auto value = [&](std::size_t i) { return std::bit_cast<float>((*words)[i]); };
  Level level(pages);
  for (std::size_t i = 0; i < pages; ++i) level[i] = {value(3 * i), value(3 * i + 1), value(3 * i + 2) != 0.0f};
  return level;
}

}  // namespace

PageRanges::PageRanges(std::int64_t nside, const std::vector<Range>& finest)
    : nside_(nside), coarsestLevel_(stripPyramid(nside).levels() - 1) {
  const int levels = coarsestLevel_ + 1;
  Level undilated = finest;
  std::vector<Level> all;
  for (int level = 0; level < levels; ++level) {
    if (level > 0) undilated = coarser(undilated, pagesAcross(nside, level - 1));
    if (undilated.size() <= kMostStoredPages)
      all.push_back(widened(undilated, pagesAcross(nside, level)));
    else
      finestStored_ = level + 1;
  }
  levels_ = std::move(all);
}

std::vector<std::pair<std::string, std::string>> PageRanges::metadataItems() const {
  std::vector<std::pair<std::string, std::string>> items;
  for (std::size_t i = 0; i < levels_.size(); ++i)
    items.emplace_back(kItemPrefix + std::to_string(finestStored_ + int(i)), encoded(levels_[i]));
  return items;
}

std::optional<PageRanges> PageRanges::fromMetadata(std::int64_t nside,
                                                   const std::function<const char*(const std::string&)>& item) {
  PageRanges ranges;
  ranges.nside_ = nside;
  ranges.coarsestLevel_ = stripPyramid(nside).levels() - 1;
  for (int level = ranges.coarsestLevel_; level >= 0; --level) {
    const char* text = item(kItemPrefix + std::to_string(level));
    if (!text) break;
    const std::int64_t side = pagesAcross(nside, level);
    std::optional<Level> decodedLevel = decoded(text, std::size_t(12 * side * side));
    if (!decodedLevel) return std::nullopt;
    ranges.levels_.insert(ranges.levels_.begin(), std::move(*decodedLevel));
    ranges.finestStored_ = level;
  }
  if (ranges.levels_.empty()) return std::nullopt;
  return ranges;
}

PageRanges::Range PageRanges::overNode(int face, int level, std::int64_t ix, std::int64_t iy) const {
  const int pageLevel = std::max(coarsestLevel_ - std::min(level, coarsestLevel_), finestStored_);
  const std::int64_t side = pagesAcross(nside_, pageLevel);
  const int shift = level - (coarsestLevel_ - pageLevel);  // node levels per page level below it
  const std::int64_t column = face * side + (ix >> shift), row = side - 1 - (iy >> shift);
  return levels_[std::size_t(pageLevel - finestStored_)][std::size_t(row * 12 * side + column)];
}

PageRanges::Range PageRanges::whole() const {
  Range all{1.0f, 0.0f};  // none held yet
  for (const Range& page : levels_.back()) {
    if (page.least > page.greatest) {
      all.uncovered = all.uncovered || page.uncovered;
      continue;
    }
    const bool first = all.least > all.greatest;
    all = {first ? page.least : std::min(all.least, page.least),
           first ? page.greatest : std::max(all.greatest, page.greatest), all.uncovered || page.uncovered};
  }
  return all;
}

}  // namespace strata::healpix
