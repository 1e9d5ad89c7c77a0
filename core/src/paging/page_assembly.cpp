#include "paging/page_assembly.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <optional>
#include <vector>

namespace strata::paging {
namespace {

// Texels of one level window, read from the source.
struct WindowTexels {
  LevelWindow window;
  std::vector<std::byte> bytes;

  WindowTexels(const PageSource& source, const LevelWindow& w)
      : window(w), bytes(std::size_t(w.width) * w.height * kPageTexelBytes) {
    source.read(window, bytes);
  }
  bool holdsColumn(int x) const { return x >= window.x && x < window.x + window.width; }
  const std::byte* texel(int x, int y) const {
    return bytes.data() + (std::size_t(y - window.y) * window.width + (x - window.x)) * kPageTexelBytes;
  }
};

// The level texels a page may be filled from: [first, last] in each direction, and whether the columns
// wrap across the level's seam.
struct ReadableRange {
  int firstColumn, lastColumn, firstRow, lastRow;
  bool wrapX;
};

// Fills the slot from the texels in `range`; texels outside it are clamped to its edges, except the one
// column across a wrapping seam. Only the first column past either edge is ever filtered against; the
// rest of a partial page is clamped like the rows.
void copyPage(const PageSource& source, const PageKey& key, const ReadableRange& range, std::span<std::byte> slot) {
  const int width = source.pyramid().levelWidth(key.level);
  const int x0 = key.column * kPagePayload - kPageBorder, y0 = key.row * kPagePayload - kPageBorder;
  const auto column = [&](int i) {
    const int x = x0 + i;
    if (range.wrapX && x == -1) return width - 1;
    if (range.wrapX && x == width) return 0;
    return std::clamp(x, range.firstColumn, range.lastColumn);
  };
  const auto row = [&](int j) { return std::clamp(y0 + j, range.firstRow, range.lastRow); };
  const int left = std::max(range.firstColumn, x0), right = std::min(range.lastColumn + 1, x0 + kPageSide);
  const int top = row(0), bottom = row(kPageSide - 1) + 1;
  const WindowTexels main(source, {key.level, left, top, right - left, bottom - top});
  // At an edge of a wrapping level the column across the seam lies outside the main window.
  std::optional<WindowTexels> seam;
  if (range.wrapX)
    for (const int i : {0, width - x0})
      if (i >= 0 && i < kPageSide && !main.holdsColumn(column(i)))
        seam.emplace(source, LevelWindow{key.level, column(i), top, 1, bottom - top});
  for (int j = 0; j < kPageSide; ++j) {
    const int y = row(j);
    std::byte* out = slot.data() + std::size_t(j) * kPageSide * kPageTexelBytes;
    for (int i = 0; i < kPageSide; ++i, out += kPageTexelBytes) {
      const int x = column(i);
      std::memcpy(out, (main.holdsColumn(x) ? main : *seam).texel(x, y), kPageTexelBytes);
    }
  }
}

}  // namespace

void assemblePage(const PageSource& source, const PageKey& key, bool wrapX, std::span<std::byte> slot) {
  const PagePyramid& pyramid = source.pyramid();
  const int width = pyramid.levelWidth(key.level), height = pyramid.levelHeight(key.level);
  try {
    copyPage(source, key, {0, width - 1, 0, height - 1, wrapX}, slot);
  } catch (const std::exception&) {
    // A neighbour's texels may be what cannot be read (a damaged tile beside this page): without them
    // the border is the page's own edge, clamped. Where the page itself is unreadable, this throws too.
    const int x0 = key.column * kPagePayload, y0 = key.row * kPagePayload;
    copyPage(source, key,
             {x0, std::min(width, x0 + kPagePayload) - 1, y0, std::min(height, y0 + kPagePayload) - 1, false}, slot);
  }
}

}  // namespace strata::paging
