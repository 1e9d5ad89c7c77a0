#include "projection_quality_layer.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/layer_capabilities.hpp>

namespace strata::composite {

ProjectionQualityLayer::ProjectionQualityLayer(const std::string& nodeId, std::vector<const Layer*> inputs)
    : prefix_("layer_" + glslIdentifier(nodeId)), inputs_(std::move(inputs)) {}

// Method 2's weight, from the input's texel steps (TexelledLayer::texelStepsFunction); 1 for inputs without texels.
std::string ProjectionQualityLayer::isotropyWeight(const Layer& input) const {
  const std::string steps = texelStepsFunctionOf(input);
  if (steps.empty()) return "1.0";
  return "projectionQualityWeight(" + steps + "(p), " + prefix_ + "_quality, " + prefix_ + "_resolution)";
}

// Method 1's weight, by the region the input's projection samples best. The node refuses the method for inputs
// that cannot tell (ProjectionAspect::Other); they count with weight 1, as under isotropy without texels.
std::string ProjectionQualityLayer::latitudeWeight(const Layer& input) const {
  const std::string band = prefix_ + "_band";
  switch (aspectOf(input)) {
    case ProjectionAspect::Equatorial: return "equatorialWeight(p.lonlat.y, " + band + ")";
    case ProjectionAspect::NorthPolar: return "polarWeight(p.lonlat.y, 1.0, " + band + ")";
    case ProjectionAspect::SouthPolar: return "polarWeight(p.lonlat.y, -1.0, " + band + ")";
    case ProjectionAspect::Other: break;
  }
  return "1.0";
}

// Each input's sample and weight into the sums. A weight is never quite 0 where an input has data, so that
// where every input weighs nothing (badly shaped texels, or outside its latitudes) they still average rather
// than leave a hole. The method is a uniform, so one program serves both.
std::string ProjectionQualityLayer::accumulation() const {
  std::string code;
  for (const Layer* input : inputs_)
    code += "  { vec4 s = " + input->samplingFunction() + "(p); float w = max(" + prefix_ + "_latitude ? " +
            latitudeWeight(*input) + " : " + isotropyWeight(*input) +
            ", 1e-4) * s.a; sum += vec4(s.rgb * w, w); coverage = max(coverage, s.a); }\n";
  return code;
}

std::string ProjectionQualityLayer::glsl() const {
  std::string code;
  for (const Layer* input : inputs_) code += input->glslOnce();
  return code +
         "#include \"composite-projection-quality/projection_quality.glsl\"\n"
         "uniform bool " +
         prefix_ +
         "_latitude;\n"
         "uniform float " +
         prefix_ +
         "_quality;\n"
         "uniform bool " +
         prefix_ +
         "_resolution;\n"
         "uniform vec2 " +
         prefix_ +
         "_band;\n"
         "vec4 " +
         prefix_ +
         "(SurfacePoint p) {\n"
         "  vec4 sum = vec4(0.0);\n"
         "  float coverage = 0.0;\n" +
         accumulation() +
         "  return sum.a > 0.0 ? vec4(sum.rgb / sum.a, coverage) : vec4(0.0);\n"
         "}\n";
}

void ProjectionQualityLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  for (const Layer* input : inputs_) input->bind(program, units);
  program.set(prefix_ + "_latitude", weighting_.method == Method::Latitude ? 1 : 0);
  program.set(prefix_ + "_quality", float(weighting_.quality));
  program.set(prefix_ + "_resolution", weighting_.resolution ? 1 : 0);
  program.set(prefix_ + "_band", glm::vec2(weighting_.band));
}

void ProjectionQualityLayer::setPageDemand(PageDemand demand) const {
  for (const Layer* input : inputs_) input->setPageDemand(demand);
}

// Weighted averages stay within the inputs' values, and where none has data the layer has none.
std::optional<ValueRange> ProjectionQualityLayer::valueRange() const { return spanningRange(inputs_); }

}  // namespace strata::composite
