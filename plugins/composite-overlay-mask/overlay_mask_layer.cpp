#include "overlay_mask_layer.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

OverlayMaskLayer::OverlayMaskLayer(const std::string& nodeId, const Layer& base, const Layer& overlay, Edge edge)
    : prefix_("layer_" + glslIdentifier(nodeId)), base_(base), overlay_(overlay), edge_(edge) {}

// The overlay's weight at `p` given its sample `over`: its coverage, or with a feather the lesser of two
// ramps, each 0 at an edge and 1 half the feather's width inside: from its distance to its raster's edge
// (edgeDistanceFunction), and from its coverage averaged over the feather's width, for the edges of its
// nodata and alpha (its texels per sample from texelStepsFunction; metres from the footprint's).
std::string OverlayMaskLayer::edgeWeight() const {
  const std::string& p = prefix_;
  if (edge_.feather <= 0.0) return "float " + p + "_weight(SurfacePoint p, vec4 over) { return over.a; }\n";
  const std::string width = edge_.metres ? p + "_feather / footprintMetres(p, " + p + "_radius) * texels" : p + "_feather";
  return "float " + p + "_weight(SurfacePoint p, vec4 over) {\n"
         "  vec4 steps = " + overlay_.texelStepsFunction() + "(p);\n"
         "  float texels = max(max(length(steps.xy), length(steps.zw)), 1e-6);  // overlay texels a sample\n"
         "  float width = " + width + ";\n"
         "  float averaged = " + overlay_.samplingFunction() + "(widenedFootprint(p, max(width / texels, 1.0))).a;\n"
         "  float fromExtent = clamp(" + overlay_.edgeDistanceFunction() + "(p) / (0.5 * width), 0.0, 1.0);\n"
         "  return min(featheredWeight(averaged), fromExtent);\n"
         "}\n";
}

std::string OverlayMaskLayer::glsl() const {
  const std::string& p = prefix_;
  return base_.glsl() + overlay_.glsl() +
         "#include \"composite/overlay_mask.glsl\"\n"
         "uniform float " + p + "_feather;\n"
         "uniform float " + p + "_radius;\n" +
         edgeWeight() +
         "vec4 " + p + "(SurfacePoint p) {\n"
         "  vec4 base = " + base_.samplingFunction() + "(p);\n"
         "  vec4 over = " + overlay_.samplingFunction() + "(p);\n"
         "  if (over.a <= 0.0) return base;  // outside the overlay: no more work\n"
         "  return overlayOver(base, over, " + p + "_weight(p, over));\n"
         "}\n";
}

void OverlayMaskLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  base_.bind(program, units);
  overlay_.bind(program, units);
  program.set(prefix_ + "_feather", float(edge_.feather));
  program.set(prefix_ + "_radius", float(edge_.radius));
}

std::optional<ValueRange> OverlayMaskLayer::valueRange() const {
  const std::optional<ValueRange> base = base_.valueRange(), overlay = overlay_.valueRange();
  if (!base || !overlay) return std::nullopt;
  return ValueRange{std::min(base->least, overlay->least), std::max(base->greatest, overlay->greatest)};
}

}  // namespace strata::composite
