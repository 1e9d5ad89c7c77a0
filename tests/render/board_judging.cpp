#include "board_judging.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "sphere_raycast.hpp"

namespace strata::test {
namespace {

std::optional<glm::ivec2> judgedCell(const View& view, double radius, const TexelBoard& board, int x, int y,
                                     bool resampled) {
  glm::dvec2 low(1e300), high(-1e300);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const std::optional<SurfaceHit> hit = raycastSphere(view, radius, x + dx, y + dy);
      if (!hit) return std::nullopt;
      const glm::dvec2 texel = board.texelOf(hit->lon, hit->lat);
      low = glm::min(low, texel);
      high = glm::max(high, texel);
    }
  const double footprint = std::max(high.x - low.x, high.y - low.y) / 2.0;  // texels a pixel
  const double coarsest = std::exp2(std::ceil(std::log2(std::max(footprint, 1.0))));
  const double margin = resampled ? std::sqrt(2.0) * coarsest + 1.0 : 0.5 * coarsest;
  low -= margin;
  high += margin;
  if (low.x < 0 || low.y < 0 || high.x > board.columns || high.y > board.rows) return std::nullopt;
  const glm::ivec2 first(glm::floor(low / double(board.cellTexels))), last(glm::floor(high / double(board.cellTexels)));
  if (first != last) return std::nullopt;
  return first;
}

}  // namespace

glm::dvec2 BoardGrid::texelOf(double lon, double lat) const {
  double east = std::remainder(lon - west, 360.0);
  if (east < 0.0 && columns * lonStep > 180.0) east += 360.0;  // a board around much of the body
  return {east / lonStep, (north - lat) / latStep};
}

Judgement judgeBoard(const Image& image, const View& view, double radius, const BoardGrid& board, bool resampled,
                     int light, int dark) {
  const TexelBoard texels{[&board](double lon, double lat) { return board.texelOf(lon, lat); }, board.columns,
                          board.rows, board.cellTexels};
  return judgeBoard(image, view, radius, texels, resampled, light, dark);
}

Judgement judgeBoard(const Image& image, const View& view, double radius, const TexelBoard& board, bool resampled,
                     int light, int dark) {
  Judgement judgement;
  for (int y = 1; y < image.height - 1; ++y)
    for (int x = 1; x < image.width - 1; ++x) {
      const std::optional<glm::ivec2> cell = judgedCell(view, radius, board, x, y, resampled);
      if (!cell) continue;
      ++judgement.judged;
      const int expected = (cell->x + cell->y) % 2 == 0 ? light : dark;
      if (std::abs(image.at(x, y)[1] - expected) > 2)
        ++judgement.wrong;  // 2 levels: 8-bit rounding after float arithmetic
    }
  return judgement;
}

std::string pipelineDegrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12f", value);
  return text;
}

}  // namespace strata::test
