#pragma once
#include <strata/export.hpp>
// The HEALPix pyramid that `strata tile --to healpix` writes and source.gdal pages from (issue 6;
// [Westerteiger et al. 2011, §3]: twelve base faces, each a quadtree of tiles; NESTED numbering). One Cloud
// Optimized GeoTIFF holds the twelve faces side by side, face f in columns [f nside, (f + 1) nside), each an
// nside x nside grid of HEALPix pixels: face f's texel (column, row) is the NESTED pixel f nside^2 +
// interleave(column, nside - 1 - row) of the HEALPix library at that nside (column bits in the even
// positions), and holds the value at that pixel's centre. Its 512x512 tiles are pages of the page cache; the
// one-sample overlap of the paper's tiles is the pages' border, which the cache fills from the neighbouring
// face on the sphere (see texelAcross), so that filtering is seamless across face edges.
//
// Finer than kMostNside (about 10 cm texels on Earth) the twelve faces no longer fit GDAL's sizes, and data
// that fine covers a small place anyway: such a pyramid holds a window of one face (kWindowItem), paged as
// any raster is, at nside up to kMostWindowedNside (6 mm texels on Earth).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include <strata/plugin/page_pyramid.hpp>
#include <strata/plugin/projection.hpp>

STRATA_EXPORTS_BEGIN
namespace strata::healpix {

// Metadata items (GDAL's default domain) that mark a file as a HEALPix pyramid and say how to read it.
inline constexpr const char* kNsideItem = "STRATA_HEALPIX_NSIDE";        // a power of two, at least kLeastNside
inline constexpr const char* kFigureItem = "STRATA_HEALPIX_CRS";         // "+proj=healpix" and the body's figure
inline constexpr const char* kOrderingItem = "STRATA_HEALPIX_ORDERING";  // "NESTED"
inline constexpr const char* kWindowItem = "STRATA_HEALPIX_WINDOW";      // a window of one face: see FaceWindow

// The least nside written: a face of one page, so that no page holds texels of two faces.
inline constexpr std::int64_t kLeastNside = kPagePayload;
// The greatest of a strip of all twelve faces: 12 nside columns fit an int, with room to spare.
inline constexpr std::int64_t kMostNside = std::int64_t{1} << 26;
// The greatest of a window of one face: face texels are still counted in an int, and strip coordinates
// (face + x, x in steps of 1 / nside) keep 20 bits to spare in a double.
inline constexpr std::int64_t kMostWindowedNside = std::int64_t{1} << 30;

// The part of face `face` a windowed pyramid holds: level-0 face texels [column, column + width) along x and
// [row, row + height) down from the face's y = 1 edge, numbered as a strip's texels are within their face.
// kWindowItem stores "face column row"; the file is width x height texels.
struct FaceWindow {
  int face = 0;
  std::int64_t column = 0;
  std::int64_t row = 0;
  int width = 0;
  int height = 0;
};

// kWindowItem's text for `window`, and the window that text and a file of `width` x `height` texels at
// `nside` describe; empty where they do not describe one within a face.
std::string windowItem(const FaceWindow& window);
std::optional<FaceWindow> windowOf(const std::string& item, std::int64_t nside, int width, int height);

// Map coordinates of the strip: x = face + the face point's x, y = the face point's y (see FacePoint), so
// that the strip's geotransform is (0, 1 / nside, 0, 1, 0, -1 / nside).
std::array<double, 6> stripGeotransform(std::int64_t nside);
// The geotransform of a windowed pyramid's texels in the same strip coordinates.
std::array<double, 6> windowGeotransform(std::int64_t nside, const FaceWindow& window);

// The strip's pages: levels halve the faces down to faces of one page (kLeastNside), never beyond, so that
// a page lies on one face at every level.
PagePyramid stripPyramid(std::int64_t nside);

// For texel `texel` of a strip level whose faces are `side` texels across, lying one texel beyond an edge or
// a corner of face `face` (column or row -1 or `side` in face texels), the strip texel of the neighbouring
// face that lies there on the sphere. Across a corner where three faces meet, one of the two faces beside
// the corner's diagonal.
glm::ivec2 texelAcross(int side, int face, glm::ivec2 texel);

// The type() of the strip's projection.
inline constexpr const char* kStripProjectionType = "healpix-faces";

// Longitude and latitude (radians) to strip map coordinates, and back, through `plane`: the planar HEALPix
// projection of the body (the CRS of kFigureItem, "+proj=healpix" with no central meridian or false origin),
// which on an ellipsoid goes through the authalic sphere as PROJ's does. At a whole x, where face f's x = 1
// edge meets face f + 1's x = 0 edge in the strip though not on the sphere, inverse() takes face f + 1's.
std::unique_ptr<Projection> stripProjection(std::shared_ptr<const Projection> plane);

// For writing face `face` with GDAL's warper: the central meridian (degrees) of the planar HEALPix CRS
// "+proj=healpix +lon_0=..." in which the face lies whole, and the face's rotated geotransform there, for
// nside texels across, in metres of the authalic radius `radius` (Projection::glslMapScale of the plane).
double faceCentralMeridian(int face);
std::array<double, 6> facePlaneGeotransform(int face, std::int64_t nside, double radius);

// True least and greatest values of a one-channel HEALPix pyramid per page, which `strata tile` computes at full
// resolution and stores in the file, so that geometry.healpix bounds each node's heights by its data rather than
// by one global range ([Westerteiger et al. 2011, §3.2.1, §3.2.2]: the paper's per-node boxes, here taken from
// per-page ranges; docs/references.md, Errata). Overview pages hold averages, whose range lies inside their
// texels' rather than around it, so the ranges cannot come from the overviews.
class PageRanges {
 public:
  struct Range {
    float least = 0.0f;  // raw values (before a layer's scale and offset); least > greatest: none held
    float greatest = 0.0f;
    bool uncovered = false;  // some texel holds no data
  };

  // From the ranges of the pages of level 0, row-major over the strip (12 nside / 512 a row): each level's
  // range of a page is widened to its eight neighbours' on the sphere (across face edges too), so that it
  // bounds whatever filtering reads for points of the page (bilinear reads one texel beyond it, a coarser
  // level's texels average a little beyond it).
  PageRanges(std::int64_t nside, const std::vector<Range>& finest);

  // The items that store the ranges in the file's metadata: those of the levels with at most kMostStoredPages
  // pages, finer ones being bounded by their ancestors'. And the ranges read back from them (`item` gives an
  // item's value, or null); empty when the file has none, or they do not fit its nside.
  std::vector<std::pair<std::string, std::string>> metadataItems() const;
  static std::optional<PageRanges> fromMetadata(std::int64_t nside,
                                                const std::function<const char*(const std::string&)>& item);

  // The widened range of the finest stored page holding node (level, ix, iy) of face `face`'s quadtree (2^level
  // nodes a side, ix along x, iy along y, as geometry.healpix numbers them).
  Range overNode(int face, int level, std::int64_t ix, std::int64_t iy) const;
  // The range of the whole pyramid: every page's, together.
  Range whole() const;
  // The finest level stored, and its pages' widened ranges, row-major over the strip (12 nside / 512 / 2^level
  // pages a row).
  int finestStoredLevel() const { return finestStored_; }
  const std::vector<Range>& finestStoredRanges() const { return levels_.front(); }

  static constexpr std::size_t kMostStoredPages = 12 * 64 * 64;  // 576 KiB of metadata at most

 private:
  PageRanges() = default;

  std::int64_t nside_ = 0;
  int coarsestLevel_ = 0;                   // the pyramid's level of faces of one page
  std::vector<std::vector<Range>> levels_;  // by level of the pyramid, finest stored first; widened
  int finestStored_ = 0;                    // the pyramid level of levels_[0]
};

}  // namespace strata::healpix
STRATA_EXPORTS_END
