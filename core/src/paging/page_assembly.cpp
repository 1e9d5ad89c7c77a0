#include "paging/page_assembly.hpp"

#include <algorithm>
#include <cstring>
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

}  // namespace

void assemblePage(const PageSource& source, const PageKey& key, bool wrapX, std::span<std::byte> slot) {
  const PagePyramid& pyramid = source.pyramid();
  const int width = pyramid.levelWidth(key.level), height = pyramid.levelHeight(key.level);
  const int x0 = key.column * kPagePayload - kPageBorder, y0 = key.row * kPagePayload - kPageBorder;
  // Only the first column past either edge is ever filtered against; the rest of a partial page is
  // clamped like the rows.
  const auto column = [&](int i) {
    const int x = x0 + i;
    if (wrapX && x == -1) return width - 1;
    if (wrapX && x == width) return 0;
    return std::clamp(x, 0, width - 1);
  };
  const auto row = [&](int j) { return std::clamp(y0 + j, 0, height - 1); };
  const int left = std::max(0, x0), right = std::min(width, x0 + kPageSide);
  const int top = row(0), bottom = row(kPageSide - 1) + 1;
  const WindowTexels main(source, {key.level, left, top, right - left, bottom - top});
  // At an edge of a wrapping level the column across the seam lies outside the main window.
  std::optional<WindowTexels> seam;
  if (wrapX)
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

}  // namespace strata::paging
