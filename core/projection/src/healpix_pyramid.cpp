// The layout of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp): the twelve faces of [Westerteiger et al. 2011,
// §3] side by side, numbered as strata/plugin/healpix.hpp numbers them.
#include <strata/plugin/healpix.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <sstream>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace strata::healpix {
namespace {

constexpr double kQuarterPi = std::numbers::pi / 4.0;

glm::dvec3 unitVectorOf(int face, glm::dvec2 xy) { return unitVector(FacePoint{face, xy.x, xy.y}); }

}  // namespace

std::array<double, 6> stripGeotransform(std::int64_t nside) {
  const double texel = 1.0 / double(nside);
  return {0.0, texel, 0.0, 1.0, 0.0, -texel};
}

std::array<double, 6> windowGeotransform(std::int64_t nside, const FaceWindow& window) {
  const double texel = 1.0 / double(nside);
  return {
      double(window.face) + double(window.column) * texel, texel, 0.0, 1.0 - double(window.row) * texel, 0.0, -texel};
}

std::string windowItem(const FaceWindow& window) {
  return std::to_string(window.face) + " " + std::to_string(window.column) + " " + std::to_string(window.row);
}

std::optional<FaceWindow> windowOf(const std::string& item, std::int64_t nside, int width, int height) {
  std::istringstream text(item);
  FaceWindow window{0, 0, 0, width, height};
  if (!(text >> window.face >> window.column >> window.row) || !(text >> std::ws).eof()) return std::nullopt;
  const bool within = window.face >= 0 && window.face < 12 && window.column >= 0 && window.row >= 0 && width > 0 &&
                      height > 0 && window.column + width <= nside && window.row + height <= nside;
  return within ? std::optional(window) : std::nullopt;
}

PagePyramid stripPyramid(std::int64_t nside) {
  // Levels 0 to log2(nside / kLeastNside): the last has faces of one page.
  const int levels = std::countr_zero(std::uint64_t(nside)) - std::countr_zero(std::uint64_t(kLeastNside)) + 1;
  return PagePyramid(int(12 * nside), int(nside), levels);
}

// In face coordinates pixels are squares, so the pixel across an edge is the one holding the midpoint of the
// inside pixel's edge seen from the other face: a point just beyond that midpoint, a thousandth of a pixel
// out (far above rounding, far below the pixel's size), floors to it. (Reflecting the pixel's centre through
// the midpoint instead lands half a pixel astray where the faces' pixels are sheared, next to the polar caps.)
glm::ivec2 texelAcross(int side, int face, glm::ivec2 texel) {
  const glm::ivec2 local(texel.x - face * side, texel.y);
  const glm::ivec2 inside = glm::clamp(local, glm::ivec2(0), glm::ivec2(side - 1));
  const glm::dvec2 centre((inside.x + 0.5) / side, 1.0 - (inside.y + 0.5) / side);
  const glm::dvec2 edge(local.x < 0       ? 0.0
                        : local.x >= side ? 1.0
                                          : centre.x,
                        local.y < 0       ? 1.0
                        : local.y >= side ? 0.0
                                          : centre.y);
  constexpr double kNudge = 1e-3;
  const glm::dvec3 onEdge = unitVectorOf(face, edge);
  const glm::dvec3 beyond = onEdge + kNudge * (onEdge - unitVectorOf(face, centre));
  const FacePoint beside =
      facePoint({std::atan2(beyond.y, beyond.x), std::atan2(beyond.z, std::hypot(beyond.x, beyond.y))});
  const int column = std::clamp(int(std::floor(beside.x * side)), 0, side - 1);
  const int row = std::clamp(int(std::floor((1.0 - beside.y) * side)), 0, side - 1);
  return {beside.face * side + column, row};
}

// Face f lies whole in the plane centred on the meridian of its column of faces (f mod 4 quarter turns),
// where it is placed as face f - f mod 4 (0, 4 or 8) is in the plane centred on longitude 0: none straddles
// the plane's east/west edge, as face 6 (centred on 180 degrees) does there.
double faceCentralMeridian(int face) { return 90.0 * (face % 4); }

std::array<double, 6> facePlaneGeotransform(int face, std::int64_t nside, double radius) {
  const glm::dvec2 west = planeOf(FacePoint{face - face % 4, 0.0, 1.0}) * radius;  // column 0, row 0
  const double step = kQuarterPi * radius / double(nside);  // a column adds (1, 1) steps, a row (1, -1)
  return {west.x, step, step, west.y, step, -step};
}

}  // namespace strata::healpix
