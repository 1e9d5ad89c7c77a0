#include "height_windows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace strata::clipmap {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSpareTexels = 4;  // one each side for the bilinear neighbour, one each side for snapping to texels
// Longitude texels step by quarter octaves: the paper's octaves (§4.1) double them just off the equator, where a cap
// spans a little more longitude than latitude, and a step's texels stay put while the viewer moves within it.
constexpr double kLongitudeSteps = 4.0;

// The lattice texel whose centre lies at or before `position` less half a texel: the first a bilinear sample at
// `position` reads, `position` in texels.
std::int64_t firstTexel(double position) { return std::int64_t(std::floor(position - 0.5)); }

// Half the longitude a cap of `angle` rad about a point at `latitude` spans ([Clasen & Hege 2006, §4.1] as corrected
// in docs/references.md, Errata), or none where the cap holds a pole.
std::optional<double> halfLongitudeExtent(double angle, double latitude) {
  if (angle >= kPi / 2.0 - std::abs(latitude)) return std::nullopt;
  return std::asin(std::min(1.0, std::sin(angle) / std::cos(latitude)));
}

// The latitude's texel times the least step of kLongitudeSteps whose window spans `halfExtent` either way, or none
// where that spans the turn.
std::optional<double> longitudeTexel(double halfExtent, double latitudeTexel, int texels) {
  const double steps =
      std::ceil(kLongitudeSteps * std::log2(2.0 * halfExtent / (latitudeTexel * (texels - kSpareTexels))));
  const double texel = latitudeTexel * std::exp2(std::max(steps, 0.0) / kLongitudeSteps);
  if (texel * texels >= 2.0 * kPi) return std::nullopt;
  return texel;
}

}  // namespace

int clipmapTexels(int steps) { return std::clamp(steps / 2, 16, 512); }

HeightWindow heightWindow(int level, glm::dvec2 reference, int texels) {
  const double angle = kPi * std::exp2(-level);
  HeightWindow window;
  window.texel.y = 2.0 * angle / (texels - kSpareTexels);
  window.origin.y = firstTexel((reference.y + kPi / 2.0 - angle) / window.texel.y);
  const std::optional<double> halfExtent = halfLongitudeExtent(angle, reference.y);
  const std::optional<double> east = halfExtent ? longitudeTexel(*halfExtent, window.texel.y, texels) : std::nullopt;
  window.wholeTurn = !east;
  window.texel.x = east ? *east : 2.0 * kPi / texels;
  if (east) window.origin.x = firstTexel((reference.x - *halfExtent) / *east);
  return window;
}

glm::ivec2 textureOffset(const HeightWindow& window, int texels) {
  const auto wrap = [texels](std::int64_t i) { return int(((i % texels) + texels) % texels); };
  return {wrap(window.origin.x), wrap(window.origin.y)};
}

glm::dvec2 cornerFromReference(const HeightWindow& window, glm::dvec2 reference) {
  return glm::dvec2(window.origin) * window.texel - glm::dvec2(reference.x, reference.y + kPi / 2.0);
}

std::vector<TexelBlock> texelsToSample(const std::optional<HeightWindow>& held, const HeightWindow& wanted,
                                       int texels) {
  const TexelBlock whole{{0, 0}, {texels, texels}};
  if (!held || held->texel != wanted.texel || held->wholeTurn != wanted.wholeTurn) return {whole};
  const glm::i64vec2 moved = wanted.origin - held->origin;
  if (std::abs(moved.x) >= texels || std::abs(moved.y) >= texels) return {whole};
  std::vector<TexelBlock> blocks;
  const auto span = [texels](std::int64_t by) {  // the first and the count of the texels moved in along one axis
    return by >= 0 ? glm::ivec2(texels - int(by), int(by)) : glm::ivec2(0, int(-by));
  };
  if (moved.x != 0) blocks.push_back({{span(moved.x).x, 0}, {span(moved.x).y, texels}});
  if (moved.y != 0) blocks.push_back({{0, span(moved.y).x}, {texels, span(moved.y).y}});
  return blocks;
}

}  // namespace strata::clipmap
