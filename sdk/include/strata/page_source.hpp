#pragma once
#include <cstddef>
#include <span>
#include <string>

#include <strata/page_pyramid.hpp>

namespace strata {

// How a page's texels are stored; both are 8 bytes a texel and carry coverage (0 at nodata) so that
// filtering never mixes nodata into values (see RasterImage).
enum class PageFormat {
  Values,  // RG32F: value x coverage, coverage. Heights need float32: half floats step by 4 m at 8 km.
  Colour,  // RGBA16F: linear r, g, b premultiplied by coverage, then coverage. Half floats keep dark
           // linear values that 8 bits would band.
};

// A rectangle of one pyramid level, in that level's texels, inside the level.
struct LevelWindow {
  int level = 0;
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

// Where a paged layer's texels come from (docs/data.md, "The page cache"). The cache asks for windows
// of pyramid levels on its loader threads and assembles pages, borders included, from them.
class PageSource {
 public:
  virtual ~PageSource() = default;

  virtual const PagePyramid& pyramid() const = 0;
  virtual PageFormat format() const = 0;
  // What to call the source in messages: its file, usually.
  virtual std::string name() const = 0;
  // Writes the texels of `window`, row-major, kPageTexelBytes each, in format(), into `texels`
  // (window.width x window.height texels). Called from several loader threads at once. Throws
  // std::exception on a read error: the cache reports it once and keeps the coarser page in place.
  virtual void read(const LevelWindow& window, std::span<std::byte> texels) const = 0;
};

}  // namespace strata
