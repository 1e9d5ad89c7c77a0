#include "grid_detail.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <strata/plugin/geometric_error.hpp>

namespace strata::pgm {
namespace {

// A cell of angle c at distance d spans c d / cos(incidence) of ground along the view: grazing ground stretches it.
// Counted down to this cosine (83 degrees): beyond it lies a band of the body's outline a pixel or two wide seen
// from orbit, and the ground toward the horizon from near it, which the thesis's grid undersamples at any size.
constexpr double kLeastCosine = 1.0 / 8.0;
constexpr double kLeastHeight = 0.01;  // m: the nearest ground counted, so that an eye on it asks for the most

glm::ivec2 halved(glm::ivec2 size) { return glm::ivec2((size - 1) >> 1) + 1; }  // (side - 1) / 2 cells

}  // namespace

double gridError(const GridScene& scene, double cell) {
  const double R = scene.radius, D = scene.eyeDistance;
  const double nearest = std::max(D - R - scene.visible.range.highest, kLeastHeight);
  const double farthest = std::max(D > R ? std::sqrt((D - R) * (D + R)) : 0.0, nearest);       // to the horizon
  const auto spacing = [&](double distance) { return cell * distance / (kLeastCosine * R); };  // rad of ground
  // Longitude and latitude are recomputed per pixel from the interpolated normal: no bending toward a pole.
  const double sphere = chordError(R, spacing(farthest), 0.5 * std::numbers::pi) / farthest;
  const double relief = scene.visible.range.highest - scene.visible.range.lowest;
  const double terrain =
      reliefWithinSpacing(relief, scene.visible.finest, scene.visibleWidth, spacing(nearest)) / nearest;
  return std::max(sphere, terrain) * scene.pixelsPerRadian;
}

glm::ivec2 gridForError(glm::ivec2 largest, glm::dvec2 extent, const GridScene& scene, double pixelError) {
  glm::ivec2 chosen = largest;
  for (glm::ivec2 size = halved(largest);
       pixelError > 0.0 && glm::all(glm::greaterThan(size, glm::ivec2(kFewestCells))); size = halved(size)) {
    const double cell = std::max(extent.x / (size.x - 1), extent.y / (size.y - 1));
    if (gridError(scene, cell) > pixelError) break;
    chosen = size;
  }
  return chosen;
}

}  // namespace strata::pgm
