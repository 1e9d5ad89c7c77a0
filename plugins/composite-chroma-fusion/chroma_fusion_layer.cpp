#include "chroma_fusion_layer.hpp"

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

ChromaFusionLayer::ChromaFusionLayer(const std::string& nodeId, const Layer& luminance, const Layer& colour,
                                     Fusion fusion)
    : prefix_("layer_" + glslIdentifier(nodeId)), luminance_(luminance), colour_(colour), fusion_(fusion) {}

// The luminance layer's relative luminance (.x) and coverage (.y) at `p`: a luminance layer's value, or a
// colour layer's luminance (Rec. 709 weights, its primaries being the composition's).
std::string ChromaFusionLayer::panLuminance() const {
  const std::string value = luminance_.kind() == LayerKind::Color ? "dot(pan.rgb, REC709_LUMINANCE)" : "pan.r";
  return "vec2 " + prefix_ +
         "_pan(SurfacePoint p) {\n"
         "  vec4 pan = " +
         luminance_.samplingFunction() +
         "(p);\n"
         "  return vec2(" +
         value +
         ", pan.a);\n"
         "}\n";
}

// The luminance layer's low-pass at the colour layer's resolution: sampled over a footprint widened to one
// colour texel, its coarser levels (box-filtered averages), as far as its pyramid reaches. A colour layer
// without texels has no resolution to take (the node refuses matching then): the luminance itself.
std::string ChromaFusionLayer::panLowpass() const {
  const std::string steps = texelStepsFunctionOf(colour_);
  const std::string scale = steps.empty() ? "1.0" : "colourTexelScale(" + steps + "(p))";
  return "float " + prefix_ +
         "_lowpass(SurfacePoint p) {\n"
         "  return " +
         prefix_ + "_pan(widenedFootprint(p, " + scale +
         ")).x;\n"
         "}\n";
}

// The fused colour over the luminance as grey: where the colour layer has no data, the grey shows with
// `strength` of the luminance's coverage; where the luminance has none, the colour alone.
std::string ChromaFusionLayer::fused() const {
  const std::string& p = prefix_;
  return "vec4 " + p +
         "(SurfacePoint p) {\n"
         "  vec4 colour = " +
         colour_.samplingFunction() +
         "(p);\n"
         "  vec2 pan = " +
         p +
         "_pan(p);\n"
         "  if (pan.y <= 0.0) return colour;\n"
         "  vec4 grey = vec4(vec3(max(pan.x, 0.0)), pan.y * " +
         p +
         "_strength);\n"
         "  if (colour.a <= 0.0) return grey.a > 0.0 ? grey : vec4(0.0);\n"
         "  float own = dot(colour.rgb, REC709_LUMINANCE);\n"
         "  float lowpass = " +
         p + "_matching == 1 ? " + p +
         "_lowpass(p) : pan.x;\n"
         "  float target = fusedLuminance(own, pan.x, lowpass, " +
         p +
         "_matching);\n"
         "  vec3 fused = chromaFusion(colour.rgb, target, " +
         p + "_strength * pan.y, " + p +
         "_space);\n"
         "  return overlayOver(grey, vec4(fused, 1.0), colour.a);\n"
         "}\n";
}

std::string ChromaFusionLayer::glsl() const {
  const std::string& p = prefix_;
  return luminance_.glslOnce() + colour_.glslOnce() +
         "#include \"composite-chroma-fusion/chroma_fusion.glsl\"\n"
         "uniform int " +
         p +
         "_space;\n"
         "uniform float " +
         p +
         "_strength;\n"
         "uniform int " +
         p + "_matching;\n" + panLuminance() + panLowpass() + fused();
}

void ChromaFusionLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  luminance_.bind(program, units);
  colour_.bind(program, units);
  program.set(prefix_ + "_space", int(fusion_.space));
  program.set(prefix_ + "_strength", float(fusion_.strength));
  program.set(prefix_ + "_matching", int(fusion_.matching));
}

void ChromaFusionLayer::setPageDemand(PageDemand demand) const {
  luminance_.setPageDemand(demand);
  colour_.setPageDemand(demand);
}

}  // namespace strata::composite
