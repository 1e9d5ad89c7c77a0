#include "temporal_blend_layer.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

TemporalBlendLayer::TemporalBlendLayer(const std::string& nodeId, std::vector<const Layer*> steps)
    : prefix_("layer_" + glslIdentifier(nodeId)), steps_(std::move(steps)) {}

void TemporalBlendLayer::show(const Bracket& bracket) {
  if (earlier_ == int(bracket.earlier) && later_ == int(bracket.later) && fraction_ == float(bracket.fraction)) return;
  earlier_ = int(bracket.earlier);
  later_ = int(bracket.later);
  fraction_ = float(bracket.fraction);
  ++reshown_;
}

bool TemporalBlendLayer::everyStepHas(FunctionOf of) const {
  return std::all_of(steps_.begin(), steps_.end(), [of](const Layer* step) { return !of(*step).empty(); });
}

// `type name(int step, parameters)`: step `step`'s function `of` at `arguments`. The step is the same for
// every sample of a frame (a uniform), so the switch costs no divergence.
std::string TemporalBlendLayer::stepDispatch(FunctionOf of, const std::string& name, const std::string& type,
                                             const std::string& parameters, const std::string& arguments) const {
  std::string code = type + " " + name + "(int step, " + parameters + ") {\n  switch (step) {\n";
  for (std::size_t i = 0; i < steps_.size(); ++i)
    code += "    case " + std::to_string(i) + ": return " + of(*steps_[i]) + "(" + arguments + ");\n";
  return code + "  }\n  return " + type + "(0.0);\n}\n";
}

// `vec4 <layer><suffix>(parameters)`: the two steps around the date through `dispatch`, blended. One call of the
// dispatch, in a loop of one round on a step's date and two between: each step's GLSL is pasted into the program
// once, not once for each bracket (a series of a dozen steps with anisotropic filtering's loops kept Mesa's
// compiler busy for minutes), and a do-while, whose test comes last, costs llvmpipe no masked extra round.
std::string TemporalBlendLayer::bracketingSteps(const std::string& dispatch, const std::string& parameters,
                                                const std::string& arguments, const std::string& suffix) const {
  const std::string& p = prefix_;
  return "vec4 " + p + suffix + "(" + parameters +
         ") {\n"
         "  vec4 bracket[2] = vec4[2](vec4(0.0), vec4(0.0));\n"
         "  int steps = " +
         p +
         "_fraction > 0.0 ? 2 : 1;  // on a step's date: one step's work\n"
         "  int i = 0;\n"
         "  do {\n"
         "    bracket[i] = " +
         dispatch + "(i == 0 ? " + p + "_earlier : " + p + "_later, " + arguments +
         ");\n"
         "  } while (++i < steps);\n"
         "  return steps == 1 ? bracket[0] : temporalBlend(bracket[0], bracket[1], " +
         p + "_fraction);\n}\n";
}

// The earlier step's texels stand for the layer's: the steps of a series share their grid as a rule.
std::string TemporalBlendLayer::texelStepsFunction() const {
  return everyStepHas(texelStepsFunctionOf) ? prefix_ + "_texelSteps" : std::string();
}

std::string TemporalBlendLayer::edgeDistanceFunction() const {
  return everyStepHas(edgeDistanceFunctionOf) ? prefix_ + "_edgeDistance" : std::string();
}

std::string TemporalBlendLayer::faceSamplingFunction() const {
  return everyStepHas(faceSamplingFunctionOf) ? prefix_ + "_faceSample" : std::string();
}

// The steps' aspect where they share one (a series of one instrument's maps), so that a temporal layer can
// feed projection_quality's latitude weighting.
ProjectionAspect TemporalBlendLayer::aspect() const {
  const ProjectionAspect first = aspectOf(*steps_.front());
  const bool shared =
      std::all_of(steps_.begin(), steps_.end(), [first](const Layer* step) { return aspectOf(*step) == first; });
  return shared ? first : ProjectionAspect::Other;
}

std::string TemporalBlendLayer::glsl() const {
  const std::string& p = prefix_;
  std::string code;
  for (const Layer* step : steps_) code += step->glslOnce();
  code +=
      "#include \"composite-temporal-blend/temporal_blend.glsl\"\n"
      "uniform int " +
      p +
      "_earlier;\n"
      "uniform int " +
      p +
      "_later;\n"
      "uniform float " +
      p + "_fraction;\n" +
      stepDispatch([](const Layer& step) { return step.samplingFunction(); }, p + "_step", "vec4", "SurfacePoint p",
                   "p") +
      bracketingSteps(p + "_step", "SurfacePoint p", "p");
  if (!texelStepsFunction().empty())
    code += stepDispatch(texelStepsFunctionOf, p + "_stepTexels", "vec4", "SurfacePoint p", "p") + "vec4 " + p +
            "_texelSteps(SurfacePoint p) { return " + p + "_stepTexels(" + p + "_earlier, p); }\n";
  if (!edgeDistanceFunction().empty())
    code += stepDispatch(edgeDistanceFunctionOf, p + "_stepEdge", "float", "SurfacePoint p", "p") + "float " + p +
            "_edgeDistance(SurfacePoint p) {\n"
            "  return max(" +
            p + "_stepEdge(" + p + "_earlier, p), " + p + "_stepEdge(" + p + "_later, p));\n}\n";
  if (!faceSamplingFunction().empty())
    code += stepDispatch(faceSamplingFunctionOf, p + "_stepFace", "vec4", "vec3 point, float footprint",
                         "point, footprint") +
            bracketingSteps(p + "_stepFace", "vec3 point, float footprint", "point, footprint", "_faceSample");
  return code;
}

void TemporalBlendLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  for (const Layer* step : steps_) step->bind(program, units);
  program.set(prefix_ + "_earlier", earlier_.load());
  program.set(prefix_ + "_later", later_.load());
  program.set(prefix_ + "_fraction", fraction_.load());
}

void TemporalBlendLayer::setPageDemand(PageDemand demand) const {
  for (const Layer* step : steps_) step->setPageDemand(demand);
}

// A blend of two steps stays within what the steps hold.
std::optional<ValueRange> TemporalBlendLayer::valueRange() const { return spanningRange(steps_); }

}  // namespace strata::composite
