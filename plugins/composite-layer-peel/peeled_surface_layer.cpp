#include "peeled_surface_layer.hpp"

#include <algorithm>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/srgb.hpp>

namespace strata::composite {
namespace {

// 5 cm: float resolves heights of some kilometres to a millimetre; a layer thinner than this is absent.
constexpr const char* kThinnest = "0.05";

}  // namespace

PeeledSurfaceLayer::PeeledSurfaceLayer(const std::string& nodeId, const PeelLayer& peel,
                                       std::vector<const Layer*> surfaces, std::vector<double> faces)
    : prefix_("layer_" + glslIdentifier(nodeId)),
      peel_(peel),
      surfaces_(std::move(surfaces)),
      faces_(std::move(faces)) {
  for (const Layer* surface : surfaces_)
    if (std::find(distinct_.begin(), distinct_.end(), surface) == distinct_.end()) distinct_.push_back(surface);
}

// Which layer shows at `shown`, given the stack's surfaces `h`: i where layer i's surface does (it lies
// there, with material beneath it), -1 - i where the cut runs through layer i's material; the floor's
// surface where nothing above it is left.
std::string PeeledSurfaceLayer::exposed() const {
  const std::string n = std::to_string(peel_.stackSize());
  return "int " + prefix_ + "_exposed(float h[" + n +
         "], float shown) {\n"
         "  for (int i = 0; i + 1 < " +
         n +
         "; ++i) {\n"
         "    if (abs(shown - h[i]) <= " +
         kThinnest + " && h[i] - h[i + 1] > " + kThinnest +
         ") return i;\n"
         "    if (shown > h[i + 1] + " +
         kThinnest +
         ") return -1 - i;\n"
         "  }\n"
         "  return " +
         std::to_string(peel_.stackSize() - 1) +
         ";\n"
         "}\n";
}

// The surface colours of layer `layer`, sampling that layer's surface alone.
std::string PeeledSurfaceLayer::surfaceColour() const {
  std::string code = "vec4 " + prefix_ + "_surface(SurfacePoint p, int layer) {\n";
  for (std::size_t i = 0; i + 1 < surfaces_.size(); ++i)
    code += "  if (layer == " + std::to_string(i) + ") return " + surfaces_[i]->samplingFunction() + "(p);\n";
  return code + "  return " + surfaces_.back()->samplingFunction() + "(p);\n}\n";
}

std::string PeeledSurfaceLayer::glsl() const {
  const std::string& p = prefix_;
  const std::string n = std::to_string(peel_.stackSize());
  std::string code = peel_.glslOnce();
  for (const Layer* surface : distinct_) code += surface->glslOnce();
  return code + "uniform vec3 " + p + "_faces[" + n + "];\n" + exposed() + surfaceColour() + "vec4 " + p +
         "(SurfacePoint p) {\n"
         "  float h[" +
         n +
         "];\n"
         "  float covered = " +
         peel_.stackFunction() +
         "(p, h);\n"
         "  if (covered <= 0.0) return vec4(0.0);\n"
         "  int layer = " +
         p + "_exposed(h, " + peel_.shownFunction() +
         "(p, h));\n"
         "  return layer < 0 ? vec4(" +
         p + "_faces[-1 - layer], covered) : " + p +
         "_surface(p, layer);\n"
         "}\n";
}

// The faces' colours decoded to scene-linear light, in which the output composes.
void PeeledSurfaceLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  peel_.bind(program, units);
  for (const Layer* surface : distinct_) surface->bind(program, units);
  for (std::size_t i = 0; i < peel_.stackSize(); ++i)
    program.set(prefix_ + "_faces[" + std::to_string(i) + "]",
                srgbToSceneLinear(faces_[3 * i], faces_[3 * i + 1], faces_[3 * i + 2]));
}

void PeeledSurfaceLayer::setPageDemand(PageDemand demand) const {
  peel_.setPageDemand(demand);
  for (const Layer* surface : distinct_) surface->setPageDemand(demand);
}

}  // namespace strata::composite
