#include "overlay_mask_layer.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

OverlayMaskLayer::OverlayMaskLayer(const std::string& nodeId, const Layer& base, const Layer& overlay,
                                   const Layer* mask, Edge edge)
    : prefix_("layer_" + glslIdentifier(nodeId)), base_(base), overlay_(overlay), mask_(mask), edge_(edge) {}

// The overlay's coverage at `p` given its sample `over` there, times the mask's weight where there is a mask:
// one footprint through which hard and feathered edges, of the overlay's data and of the mask, all pass.
std::string OverlayMaskLayer::coverage() const {
  const std::string masked = mask_ ? " * maskWeight(" + mask_->samplingFunction() + "(p))" : "";
  return "float " + prefix_ + "_coverage(SurfacePoint p, vec4 over) { return over.a" + masked + "; }\n";
}

// The overlay's weight at `p` given its coverage there: that coverage, or with a feather the lesser of two
// ramps, each 0 at an edge and 1 about half the feather's width inside: from its distance to its raster's
// edge (edgeDistanceFunction), and from its masked coverage averaged over half the feather's width, for the
// edges of its nodata, its alpha and its mask (its texels per sample from texelStepsFunction; metres from the
// footprint's). The averages are a box pyramid's levels, filtered bilinearly between texels and linearly
// between levels, so the second ramp reaches 1 between a quarter and the whole of the width, as the edge
// falls in their texels; averaging over half the width centres that on half of it.
std::string OverlayMaskLayer::edgeWeight() const {
  const std::string& p = prefix_;
  if (edge_.feather <= 0.0) return "float " + p + "_weight(SurfacePoint p, float coverage) { return coverage; }\n";
  const std::string width =
      edge_.metres ? p + "_feather / footprintMetres(p, " + p + "_radius) * texels" : p + "_feather";
  return "float " + p +
         "_weight(SurfacePoint p, float coverage) {\n"
         "  vec4 steps = " +
         texelStepsFunctionOf(overlay_) +
         "(p);\n"
         "  float texels = max(max(length(steps.xy), length(steps.zw)), 1e-6);  // overlay texels a sample\n"
         "  float width = " +
         width +
         ";\n"
         "  SurfacePoint wide = widenedFootprint(p, max(0.5 * width / texels, 1.0));\n"
         "  float averaged = " +
         p + "_coverage(wide, " + overlay_.samplingFunction() +
         "(wide));\n"
         "  float fromExtent = clamp(" +
         edgeDistanceFunctionOf(overlay_) +
         "(p) / (0.5 * width), 0.0, 1.0);\n"
         "  return min(featheredWeight(averaged), fromExtent);\n"
         "}\n";
}

std::string OverlayMaskLayer::glsl() const {
  const std::string& p = prefix_;
  return base_.glslOnce() + overlay_.glslOnce() + (mask_ ? mask_->glslOnce() : std::string()) +
         "#include \"composite-overlay-mask/overlay_mask.glsl\"\n"
         "uniform float " +
         p +
         "_feather;\n"
         "uniform float " +
         p + "_radius;\n" + coverage() + edgeWeight() + "vec4 " + p +
         "(SurfacePoint p) {\n"
         "  vec4 base = " +
         base_.samplingFunction() +
         "(p);\n"
         "  vec4 over = " +
         overlay_.samplingFunction() +
         "(p);\n"
         "  if (over.a <= 0.0) return base;  // outside the overlay: no more work\n"
         "  float coverage = " +
         p +
         "_coverage(p, over);\n"
         "  if (coverage <= 0.0) return base;  // masked away\n"
         "  return overlayOver(base, over, " +
         p +
         "_weight(p, coverage));\n"
         "}\n";
}

void OverlayMaskLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  base_.bind(program, units);
  overlay_.bind(program, units);
  if (mask_) mask_->bind(program, units);
  program.set(prefix_ + "_feather", float(edge_.feather));
  program.set(prefix_ + "_radius", float(edge_.radius));
}

void OverlayMaskLayer::setPageDemand(PageDemand demand) const {
  base_.setPageDemand(demand);
  overlay_.setPageDemand(demand);
  if (mask_) mask_->setPageDemand(demand);
}

std::optional<ValueRange> OverlayMaskLayer::valueRange() const { return spanningRange({&base_, &overlay_}); }

}  // namespace strata::composite
