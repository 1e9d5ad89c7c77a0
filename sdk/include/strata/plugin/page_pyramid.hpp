#pragma once
#include <compare>
#include <cstddef>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Pages of 512x512 texels plus a 1-texel border copied from their neighbours, 514x514 in the cache, so
// that bilinear filtering is seamless across page edges ([Kooima 2008, §4.3.1]: about 500x500 tested
// best; 512 matches the COG tiles `strata tile` writes, so a page is one tile and its neighbours' edges).
inline constexpr int kPagePayload = 512;
inline constexpr int kPageBorder = 1;
inline constexpr int kPageSide = kPagePayload + 2 * kPageBorder;
// Every page format holds 8 bytes per texel (see PageFormat).
inline constexpr std::size_t kPageTexelBytes = 8;
inline constexpr std::size_t kPageBytes = std::size_t(kPageSide) * kPageSide * kPageTexelBytes;

// One page: its level (0 is the raster's own resolution) and its column and row in that level.
struct PageKey {
  int level = 0;
  int column = 0;
  int row = 0;
  auto operator<=>(const PageKey&) const = default;
};

// The mip pyramid of pages over a raster ([Kooima 2008, §4.3.1]): level 0 is the raster, each level
// halves the one below (a texel of level l covers 2^l x 2^l raster texels; the last row and column may
// cover less), up to the first level that fits in one page.
class PagePyramid {
 public:
  PagePyramid() = default;
  PagePyramid(int width, int height);
  // The same, stopping after `mostLevels` levels (at least 1) where the pyramid would go on.
  PagePyramid(int width, int height, int mostLevels);

  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return levels_; }
  int levelWidth(int level) const;  // texels across level `level`: width / 2^level, rounded up
  int levelHeight(int level) const;
  int pagesAcross(int level) const;
  int pagesDown(int level) const;
  std::size_t pageCount(int level) const { return std::size_t(pagesAcross(level)) * pagesDown(level); }
  bool contains(const PageKey& key) const;

 private:
  int width_ = 0;
  int height_ = 0;
  int levels_ = 0;
};

}  // namespace strata
STRATA_EXPORTS_END
