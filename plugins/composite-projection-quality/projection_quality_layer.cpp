#include "projection_quality_layer.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

ProjectionQualityLayer::ProjectionQualityLayer(const std::string& nodeId, std::vector<const Layer*> inputs)
    : prefix_("layer_" + glslIdentifier(nodeId)), inputs_(std::move(inputs)) {}

void ProjectionQualityLayer::setWeighting(double quality, bool resolution) {
  quality_ = quality;
  resolution_ = resolution;
}

// Each input's sample and weight into the sums. A weight is never quite 0 where an input has data, so that
// where every input is badly shaped they still average rather than leave a hole.
std::string ProjectionQualityLayer::accumulation() const {
  std::string code;
  for (const Layer* input : inputs_) {
    const std::string steps = input->texelStepsFunction();
    const std::string weight = steps.empty() ? "1.0"
                                             : "projectionQualityWeight(" + steps + "(p), " + prefix_ + "_quality, " +
                                                   prefix_ + "_resolution)";
    code += "  { vec4 s = " + input->samplingFunction() + "(p); float w = max(" + weight +
            ", 1e-4) * s.a; sum += vec4(s.rgb * w, w); coverage = max(coverage, s.a); }\n";
  }
  return code;
}

std::string ProjectionQualityLayer::glsl() const {
  std::string code;
  for (const Layer* input : inputs_) code += input->glsl();
  return code +
         "#include \"composite/projection_quality.glsl\"\n"
         "uniform float " + prefix_ + "_quality;\n"
         "uniform bool " + prefix_ + "_resolution;\n"
         "vec4 " + prefix_ + "(SurfacePoint p) {\n"
         "  vec4 sum = vec4(0.0);\n"
         "  float coverage = 0.0;\n" +
         accumulation() +
         "  return sum.a > 0.0 ? vec4(sum.rgb / sum.a, coverage) : vec4(0.0);\n"
         "}\n";
}

void ProjectionQualityLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  for (const Layer* input : inputs_) input->bind(program, units);
  program.set(prefix_ + "_quality", float(quality_));
  program.set(prefix_ + "_resolution", resolution_ ? 1 : 0);
}

// Weighted averages stay within the inputs' values, and where none has data the layer has none.
std::optional<ValueRange> ProjectionQualityLayer::valueRange() const {
  std::optional<ValueRange> range;
  for (const Layer* input : inputs_) {
    const std::optional<ValueRange> own = input->valueRange();
    if (!own) return std::nullopt;
    range = range ? ValueRange{std::min(range->least, own->least), std::max(range->greatest, own->greatest)} : *own;
  }
  return range;
}

}  // namespace strata::composite
