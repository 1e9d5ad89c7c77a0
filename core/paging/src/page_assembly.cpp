#include "paging/page_assembly.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <optional>
#include <vector>

#include <glm/common.hpp>

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

// Where a texel lies against [first, last]: -1 or 1 one before or after it, 0 in it, 2 further out.
int sideOf(int v, int first, int last) {
  if (v == first - 1) return -1;
  if (v == last + 1) return 1;
  return v < first || v > last ? 2 : 0;
}

// A slot texel one beyond the page's grid, and the level texel the source places there.
struct Beside {
  std::size_t slotTexel;
  glm::ivec2 texel;
};
using BesideGroups = std::array<std::vector<Beside>, 9>;  // by side: (dx + 1) + 3 (dy + 1)

// The slot texels one beyond the grid `range` that the source places elsewhere in the level (PageSource::
// texelBeside: another face's edge), grouped by the side or corner they lie beyond.
BesideGroups besideGroups(const PageSource& source, const PageKey& key, const ReadableRange& range, glm::ivec2 origin) {
  BesideGroups groups;
  for (int j = 0; j < kPageSide; ++j)
    for (int i = 0; i < kPageSide; ++i) {
      const glm::ivec2 at = origin + glm::ivec2(i, j);
      const int dx = range.wrapX ? 0 : sideOf(at.x, range.firstColumn, range.lastColumn);
      const int dy = sideOf(at.y, range.firstRow, range.lastRow);
      if ((dx == 0 && dy == 0) || dx == 2 || dy == 2) continue;
      if (const std::optional<glm::ivec2> texel = source.texelBeside(key, at))
        groups[std::size_t(dx + 1 + 3 * (dy + 1))].push_back({std::size_t(j) * kPageSide + std::size_t(i), *texel});
    }
  return groups;
}

// Copies the texels beside the grid into the slot, each group read as one window: a line of texels along
// the neighbouring grid's edge, or one texel beyond a corner.
void copyBeside(const PageSource& source, const PageKey& key, const ReadableRange& range, glm::ivec2 origin,
                std::span<std::byte> slot) {
  for (const std::vector<Beside>& group : besideGroups(source, key, range, origin)) {
    if (group.empty()) continue;
    glm::ivec2 low = group.front().texel, high = low;
    for (const Beside& b : group) low = glm::min(low, b.texel), high = glm::max(high, b.texel);
    const WindowTexels window(source, {key.level, low.x, low.y, high.x - low.x + 1, high.y - low.y + 1});
    for (const Beside& b : group)
      std::memcpy(slot.data() + b.slotTexel * kPageTexelBytes, window.texel(b.texel.x, b.texel.y), kPageTexelBytes);
  }
}

// Fills the slot from the texels in `range`; texels outside it are clamped to its edges, except the one
// column across a wrapping seam, and, with `beside`, the texels one beyond a grid's edge that the source
// places elsewhere. Only the first column past either edge is ever filtered against; the rest of a partial
// page is clamped like the rows.
void copyPage(const PageSource& source, const PageKey& key, const ReadableRange& range, bool beside,
              std::span<std::byte> slot) {
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
  if (beside) copyBeside(source, key, range, {x0, y0}, slot);
}

}  // namespace

void assemblePage(const PageSource& source, const PageKey& key, bool wrapX, std::span<std::byte> slot) {
  const LevelWindow grid = source.gridOf(key);
  try {
    copyPage(source, key, {grid.x, grid.x + grid.width - 1, grid.y, grid.y + grid.height - 1, wrapX}, true, slot);
  } catch (const std::exception&) {
    // A neighbour's texels may be what cannot be read (a damaged tile beside this page): without them
    // the border is the page's own edge, clamped. Where the page itself is unreadable, this throws too.
    const int x0 = key.column * kPagePayload, y0 = key.row * kPagePayload;
    copyPage(source, key,
             {x0, std::min(grid.x + grid.width, x0 + kPagePayload) - 1, y0,
              std::min(grid.y + grid.height, y0 + kPagePayload) - 1, false},
             false, slot);
  }
}

}  // namespace strata::paging
