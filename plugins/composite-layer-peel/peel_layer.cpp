#include "peel_layer.hpp"

#include <strata/gl/shader_program.hpp>

namespace strata::composite {

PeelLayer::PeelLayer(const std::string& nodeId, std::vector<const Layer*> stack, Peel peel, Cutaway cutaway,
                     double radius)
    : prefix_("layer_" + glslIdentifier(nodeId)),
      stack_(std::move(stack)),
      peel_(peel),
      cutaway_(cutaway),
      radius_(radius) {}

// The stack's surfaces from the floor up, each lifted to the one beneath where the data put it lower and
// taking that one's height where it has no data (mixed by its coverage at its edges); then, from the top
// down, a layer beneath with no data sits at the surface above it.
std::string PeelLayer::stacked() const {
  const std::string n = std::to_string(stack_.size()), last = std::to_string(stack_.size() - 1);
  std::string code = "float " + stackFunction() + "(SurfacePoint p, out float h[" + n +
                     "]) {\n"
                     "  vec4 s = " +
                     stack_.back()->samplingFunction() +
                     "(p);\n"
                     "  h[" +
                     last +
                     "] = s.r;\n"
                     "  float covered = s.a;\n";
  for (std::size_t i = stack_.size() - 1; i-- > 0;) {
    const std::string layer = std::to_string(i), below = std::to_string(i + 1);
    code += "  s = " + stack_[i]->samplingFunction() +
            "(p);\n"
            "  h[" +
            layer + "] = covered > 0.0 ? mix(h[" + below + "], max(s.r, h[" + below +
            "]), s.a) : s.r;\n"
            "  covered = max(covered, s.a);\n";
  }
  return code + "  for (int i = 1; i < " + n +
         "; ++i) h[i] = min(h[i], h[i - 1]);\n"
         "  return covered;\n"
         "}\n";
}

std::string PeelLayer::shown() const {
  const std::string& p = prefix_;
  const std::string n = std::to_string(stack_.size()), last = std::to_string(stack_.size() - 1);
  return "float " + shownFunction() + "(SurfacePoint p, float h[" + n +
         "]) {\n"
         "  float peeled = max(h[" +
         last + "], h[" + p + "_peel] - " + p +
         "_depth);\n"
         "  return mix(h[0], peeled, cutawayWeight(p, " +
         p +
         "_cutaway));\n"
         "}\n";
}

std::string PeelLayer::glsl() const {
  const std::string& p = prefix_;
  std::string code;
  for (const Layer* layer : stack_) code += layer->glslOnce();
  return code +
         "#include \"composite-layer-peel/layer_peel.glsl\"\n"
         "uniform int " +
         p +
         "_peel;\n"
         "uniform float " +
         p +
         "_depth;\n"
         "uniform Cutaway " +
         p + "_cutaway;\n" + stacked() + shown() + "vec4 " + p +
         "(SurfacePoint p) {\n"
         "  float h[" +
         std::to_string(stack_.size()) +
         "];\n"
         "  float covered = " +
         stackFunction() +
         "(p, h);\n"
         "  return vec4(" +
         shownFunction() +
         "(p, h), 0.0, 0.0, covered);\n"
         "}\n";
}

void PeelLayer::repeel(Peel peel, Cutaway cutaway) {
  peel_ = peel;
  cutaway_ = cutaway;
  ++repeeled_;
}

void PeelLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  for (const Layer* layer : stack_) layer->bind(program, units);
  program.set(prefix_ + "_peel", peel_.layers);
  program.set(prefix_ + "_depth", float(peel_.depth));
  cutaway_.bind(program, prefix_ + "_cutaway", radius_);
}

void PeelLayer::setPageDemand(PageDemand demand) const {
  for (const Layer* layer : stack_) layer->setPageDemand(demand);
}

}  // namespace strata::composite
