#include "drawn_levels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strata::clipmap {
namespace {

// The angle at the body's centre from a point `height` above a sphere of `sphere` to its horizon on that sphere.
double horizonAngle(double sphere, double height) {
  return std::acos(std::clamp(sphere / (sphere + std::max(height, 0.0)), -1.0, 1.0));
}

// The level whose span holds theta~ `colatitude`: pi 2^-(i+1) < colatitude <= pi 2^-i.
int levelHolding(double colatitude) { return int(std::floor(std::log2(std::numbers::pi / colatitude))); }

}  // namespace

double horizonColatitude(double radius, double altitude, const HeightRange& heights) {
  const double lowest = radius + std::min(heights.lowest, 0.0);
  const double seen = horizonAngle(lowest, radius + altitude - lowest);
  return std::min(seen + horizonAngle(lowest, radius + heights.highest - lowest), std::numbers::pi);
}

double pixelColatitude(double radius, double altitude, const HeightRange& heights, double pixelAngle) {
  const double aboveGround = altitude - groundLevelNear(heights, altitude);
  return std::max(aboveGround, 0.0) * std::tan(pixelAngle) / radius;
}

double capColatitude(double pixel) { return kCapPixels * pixel; }

DrawnLevels drawnLevels(double horizon, double cap, int levels) {
  const int coarsest = std::clamp(levelHolding(horizon), 0, levels - 1);
  const int finest = cap > 0.0 ? std::clamp(levelHolding(cap), coarsest, levels - 1) : levels - 1;
  return {coarsest, finest};
}

}  // namespace strata::clipmap
