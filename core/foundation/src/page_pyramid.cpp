#include <algorithm>
#include <cstdint>

#include <strata/plugin/page_pyramid.hpp>

namespace strata {

PagePyramid::PagePyramid(int width, int height) : width_(width), height_(height), levels_(1) {
  while (levelWidth(levels_ - 1) > kPagePayload || levelHeight(levels_ - 1) > kPagePayload) ++levels_;
}

PagePyramid::PagePyramid(int width, int height, int mostLevels) : PagePyramid(width, height) {
  levels_ = std::clamp(mostLevels, 1, levels_);
}

int PagePyramid::levelWidth(int level) const {
  return int((std::int64_t(width_) + (std::int64_t(1) << level) - 1) >> level);
}

int PagePyramid::levelHeight(int level) const {
  return int((std::int64_t(height_) + (std::int64_t(1) << level) - 1) >> level);
}

int PagePyramid::pagesAcross(int level) const { return (levelWidth(level) + kPagePayload - 1) / kPagePayload; }

int PagePyramid::pagesDown(int level) const { return (levelHeight(level) + kPagePayload - 1) / kPagePayload; }

bool PagePyramid::contains(const PageKey& key) const {
  return key.level >= 0 && key.level < levels_ && key.column >= 0 && key.column < pagesAcross(key.level) &&
         key.row >= 0 && key.row < pagesDown(key.level);
}

}  // namespace strata
