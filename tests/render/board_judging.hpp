#pragma once
// Judging a rendered checkerboard of longitude/latitude texels against a ray cast in double: the precision
// tests' rule (raster_precision_test.cpp, wide_raster_precision_test.cpp).
#include <functional>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include <strata/camera.hpp>

#include "test_rasters.hpp"

namespace strata::test {

// Where a board's texels lie: texel (x, y) covers longitudes west + [x, x + 1) lonStep and latitudes
// north - [y, y + 1) latStep (degrees); cells of `cellTexels` a side alternate light and dark, light where
// the cell's column and row add up to an even number.
struct BoardGrid {
  double west = 0.0, north = 0.0;
  double lonStep = 0.0, latStep = 0.0;
  int columns = 0, rows = 0;
  int cellTexels = 16;
  // Level-0 texel position (x east, y south) of a longitude and latitude, the longitude wrapped to the board.
  glm::dvec2 texelOf(double lon, double lat) const;
};

struct Judgement {
  int judged = 0;  // pixels whose filtered texels lie in one cell
  int wrong = 0;   // of those, pixels not showing that cell's grey within 2 levels
};

// A board of texels in any projection: the level-0 texel position (x east, y south) of a longitude and latitude
// (degrees), its size in texels, and its cells' side in texels.
struct TexelBoard {
  std::function<glm::dvec2(double lon, double lat)> texelOf;
  int columns = 0, rows = 0;
  int cellTexels = 16;
};

// Every pixel whose texel footprint lies in one cell, by a ray cast in double against the sphere of `radius`:
// its 3x3 neighbourhood's hits, widened by what filtering reads beyond a point (half a texel of the coarser
// of the two mip levels the footprint blends, 2^ceil(log2 footprint) level-0 texels), must fall in a single
// cell. `resampled`: a board warped into another projection, whose bilinear resampling blurs each edge over
// a texel and whose mip levels are not aligned with the cells: a whole coarse texel (turned, up to sqrt 2
// of it along the board's axes) and one more texel on each side.
Judgement judgeBoard(const Image& image, const View& view, double radius, const TexelBoard& board, bool resampled,
                     int light, int dark);
Judgement judgeBoard(const Image& image, const View& view, double radius, const BoardGrid& board, bool resampled,
                     int light, int dark);

// Degrees as a pipeline's text, to twelve places (a micrometre on Earth).
std::string pipelineDegrees(double value);

}  // namespace strata::test
