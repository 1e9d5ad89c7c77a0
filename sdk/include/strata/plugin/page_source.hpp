#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <strata/export.hpp>
#include <string>

#include <glm/vec2.hpp>

#include <strata/plugin/page_pyramid.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// How a page's texels are stored; both are 8 bytes a texel and carry coverage (0 at nodata) so that
// filtering never mixes nodata into values (see RasterImage).
enum class PageFormat {
  Values,  // RG32F: value x coverage, coverage. Heights need float32: half floats step by 4 m at 8 km.
  Colour,  // RGBA16F: r, g, b premultiplied by coverage, then coverage; scene-linear once in the atlas
           // (PageSource::toSceneLinearGlsl). Half floats keep dark linear values that 8 bits would band.
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

  // A pyramid whose levels are several grids side by side (the twelve faces of a HEALPix pyramid,
  // strata/plugin/healpix_pyramid.hpp) says which grid page `key` lies on, and which level texel lies on the body
  // next to a texel one beyond that grid's edge: the cache fills the page's border from there, so that
  // filtering runs on across the edge. By default a level is one grid, and beyond its edges the border
  // repeats the edge (or wraps round, for a raster around the body).
  virtual LevelWindow gridOf(const PageKey& key) const;
  virtual std::optional<glm::ivec2> texelBeside(const PageKey& key, glm::ivec2 texel) const;

  // A Colour source whose texels are encoded in a colour space other than scene-linear (8-bit images are
  // mostly sRGB) returns GLSL 4.50 `vec4 functionName(vec4 colour)` that converts one texel, not
  // premultiplied, to scene-linear: ColourConfig::toSceneLinear()'s. The cache runs it on each page right
  // after uploading it, so that filtering mixes linear light. By default empty: the texels are
  // scene-linear already.
  virtual std::string toSceneLinearGlsl(const std::string& functionName) const;
};

}  // namespace strata
STRATA_EXPORTS_END
