// composite.peeled_surface: the colours of what a composite.layer_peel shows, each layer's imagery on its
// surface and its colour on the faces the cut makes ([Kooima 2008, §1.1, ch. 6], layered data peeling).
#include <memory>

#include <strata/plugin/node.hpp>
#include <strata/plugin/parameter_bindings.hpp>

#include "declarations.hpp"
#include "peeled_surface_layer.hpp"
#include "plugin_shaders.hpp"

namespace strata::composite {
namespace {

const PeelLayer& peelOf(const NodeSetup& setup) {
  const auto* peel = dynamic_cast<const PeelLayer*>(setup.input("peel")->layer());
  if (!peel)
    throw Error(setup.where, "its peel is not a composite.layer_peel node",
                "give the composite.layer_peel whose surface to colour, the node the geometry's height is");
  return *peel;
}

std::vector<const Layer*> surfacesOf(const NodeSetup& setup, const PeelLayer& peel) {
  const std::vector<Node*>& nodes = setup.inputList("surfaces");
  if (nodes.size() != peel.stackSize())
    throw Error(setup.where,
                "it has " + std::to_string(nodes.size()) + " surfaces for a stack of " +
                    std::to_string(peel.stackSize()) + " layers",
                "give one colour layer per layer of the stack, top first");
  std::vector<const Layer*> surfaces;
  for (Node* node : nodes) surfaces.push_back(node->layer());
  return surfaces;
}

// The colours as a pipeline writes them, each default's reason beside it.
struct FacesSettings {
  // ice blue, rock brown, sediment ochre, basement grey: apart at a glance, for stacks of up to four
  std::vector<double> faces{0.7, 0.85, 1.0, 0.55, 0.4, 0.3, 0.8, 0.65, 0.35, 0.5, 0.5, 0.5};
};

// A uniform: the faces' colours change the next frame.
const ParameterBindings<FacesSettings>& facesParameters() {
  using S = FacesSettings;
  static const auto bindings = ParameterBindings<S>().add(
      &S::faces, {.name = "faces",
                  .minimum = 0.0,
                  .maximum = 1.0,
                  .doc = "the colour of each layer's cut faces, where the cut runs through its material: red, green, "
                         "blue (sRGB, 0 to 1) per layer, top first",
                  .live = true});
  return bindings;
}

std::vector<double> facesOf(const ParameterSet& parameters, const PeelLayer& peel) {
  const std::vector<double> faces = facesParameters().read(parameters).faces;
  if (faces.size() % 3 != 0 || faces.size() < 3 * peel.stackSize())
    throw Error(facesParameters().where(parameters, &FacesSettings::faces),
                "faces has " + std::to_string(faces.size()) + " numbers, not three for each of the stack's " +
                    std::to_string(peel.stackSize()) + " layers",
                "give red, green, blue (sRGB, 0 to 1) for each layer, top first");
  return faces;
}

class PeeledSurface : public Node {
 public:
  explicit PeeledSurface(const NodeSetup& setup)
      : peel_(peelOf(setup)), layer_(setup.id, peel_, surfacesOf(setup, peel_), facesOf(setup.parameters, peel_)) {}

  Layer* layer() override { return &layer_; }
  void update(const ParameterSet& parameters) override { layer_.recolour(facesOf(parameters, peel_)); }

 private:
  const PeelLayer& peel_;
  PeeledSurfaceLayer layer_;
};

}  // namespace

NodeTypeDeclaration peeledSurfaceDeclaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.peeled_surface";
  type.category = NodeCategory::Compositor;
  type.summary = "The colours of what a composite.layer_peel shows: each layer's surface, and its cut faces";
  type.inputs = {{.name = "peel",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Height},
                  .doc = "the composite.layer_peel whose surface to colour"},
                 {.name = "surfaces",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Color},
                  .list = true,
                  .doc = "one colour layer per layer of the stack, top first: what its surface shows"}};
  type.output = PortType::Layer;
  type.parameters = facesParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<PeeledSurface>(setup); };
  return type;
}

}  // namespace strata::composite
