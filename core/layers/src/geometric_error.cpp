#include <algorithm>
#include <cmath>

#include <strata/plugin/geometric_error.hpp>

namespace strata {

double chordError(double radius, double spacing, double fromPole) {
  const double theta = std::max(fromPole, spacing);
  return chordSagitta(radius, spacing) * (1.0 + 1.0 / std::tan(theta));
}

double chordSagitta(double radius, double spacing) { return radius * spacing * spacing / 8.0; }

double reliefWithinSpacing(double relief, const std::optional<BlockRelief>& finest, double width, double spacing) {
  if (relief <= 0.0) return 0.0;
  double roughness = 0.5;
  if (finest && finest->width < width)
    roughness = finest->range > 0.0
                    ? std::clamp(std::log(relief / finest->range) / std::log(width / finest->width), 0.5, 1.0)
                    : 1.0;
  const double firstOrder = relief * std::pow(std::min(spacing / width, 1.0), roughness);
  if (!finest) return firstOrder;
  const double span = std::max(spacing, finest->texel);
  return std::min(firstOrder, finest->curvature * span * span / 4.0);
}

}  // namespace strata
