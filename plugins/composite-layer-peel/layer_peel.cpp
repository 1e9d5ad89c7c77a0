// composite.layer_peel: a stack of height layers as one, its upper layers peeled away by a peel depth within a
// cutaway region ([Kooima 2008, §1.1, ch. 6], layered data peeling).
#include <memory>
#include <set>

#include <strata/plugin/node.hpp>
#include <strata/plugin/parameter_bindings.hpp>

#include "declarations.hpp"
#include "peel_layer.hpp"
#include "plugin_shaders.hpp"

namespace strata::composite {
namespace {

// Two to sixteen layers, each once: one node twice would paste its GLSL into the program twice.
std::vector<const Layer*> stackOf(const NodeSetup& setup) {
  const std::vector<Node*>& nodes = setup.inputList("layers");
  if (nodes.size() < 2)
    throw Error(setup.where, "a stack needs two layers or more, and has " + std::to_string(nodes.size()),
                "give the layers top first, e.g. layers: [ice-surface, bedrock]");
  if (std::set<Node*>(nodes.begin(), nodes.end()).size() != nodes.size())
    throw Error(setup.where, "a layer appears twice in the stack", "give each layer of the stack once, top first");
  std::vector<const Layer*> stack;
  for (Node* node : nodes) stack.push_back(node->layer());
  return stack;
}

// The peel as a pipeline writes it, each default's reason beside it.
struct PeelSettings {
  std::int64_t layers = 1;  // the top layer taken away, which shows the next one: what a stack of two is peeled for
  double depth = 0.0;       // the surface the peel exposes, as its data have it
};

// Every parameter is a uniform: the peel and the cutaway change the next frame.
const ParameterBindings<PeelSettings>& peelParameters() {
  using S = PeelSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::layers, {.name = "peel",
                            .minimum = 0.0,
                            .maximum = 15.0,
                            .doc = "how many of the upper layers the cut takes away (at most all but the floor)",
                            .live = true})
          .add(&S::depth, {.name = "depth",
                           .minimum = 0.0,
                           .maximum = 1.0e6,
                           .units = "m",
                           .doc = "how far the cut goes below the surface the peel exposes, never below the floor",
                           .live = true});
  return bindings;
}

// The peel, of a stack of `stackSize` layers.
PeelLayer::Peel peelOf(const ParameterSet& parameters, std::size_t stackSize) {
  const PeelSettings settings = peelParameters().read(parameters);
  const auto most = std::int64_t(stackSize) - 1;
  if (settings.layers > most)
    throw Error(peelParameters().where(parameters, &PeelSettings::layers),
                "peel " + std::to_string(settings.layers) + " takes away more layers than lie above the floor (" +
                    std::to_string(most) + ")",
                "peel at most " + std::to_string(most) + ": the last layer is the floor");
  return {int(settings.layers), settings.depth};
}

class LayerPeel : public Node {
 public:
  explicit LayerPeel(const NodeSetup& setup) : layer_(peelLayerOf(setup)), stackSize_(layer_.stackSize()) {}

  Layer* layer() override { return &layer_; }
  void update(const ParameterSet& parameters) override {
    layer_.repeel(peelOf(parameters, stackSize_), Cutaway::from(parameters));
  }

 private:
  // The stack checked before the peel, which counts its layers.
  static PeelLayer peelLayerOf(const NodeSetup& setup) {
    std::vector<const Layer*> stack = stackOf(setup);
    const PeelLayer::Peel peel = peelOf(setup.parameters, stack.size());
    return PeelLayer(setup.id, std::move(stack), peel, Cutaway::from(setup.parameters), setup.body->radius);
  }

  PeelLayer layer_;
  std::size_t stackSize_;
};

}  // namespace

NodeTypeDeclaration layerPeelDeclaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.layer_peel";
  type.category = NodeCategory::Compositor;
  type.summary = "A stack of height layers as one, its upper layers peeled away by a depth within a cutaway";
  type.inputs = {{.name = "layers",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Height},
                  .list = true,
                  .doc = "the stack's height layers, top first (ice surface, bedrock); the last is the floor"}};
  type.output = PortType::Layer;
  type.parameters = peelParameters().declarations();
  for (ParameterDeclaration& parameter : Cutaway::parameters()) type.parameters.push_back(std::move(parameter));
  type.create = [](const NodeSetup& setup) { return std::make_unique<LayerPeel>(setup); };
  return type;
}

}  // namespace strata::composite
