// composite.projection_quality: layers of one kind, in any projections, blended sample by sample by how well
// each is sampled where it lands (seed 000 section 4.1; digest 000 section 5.1), so that a global map and
// polar caps compose into one layer sharp at the equator and at the poles, with no seam where they cross.
#include <memory>

#include <strata/node.hpp>
#include <strata/node_type.hpp>
#include <strata/plugin.hpp>

#include "projection_quality_layer.hpp"

namespace strata::composite {
namespace {

std::vector<const Layer*> inputLayers(const NodeSetup& setup) {
  std::vector<const Layer*> layers;
  for (Node* node : setup.inputList("layers")) layers.push_back(node->layer());
  for (const Layer* layer : layers)
    if (layer->kind() != layers.front()->kind())
      throw Error(setup.where, "the layers are of different kinds (" + std::string(toString(layers.front()->kind())) +
                                   " and " + toString(layer->kind()) + "), which cannot be blended",
                  "give layers of one kind: heights with heights, colours with colours");
  return layers;
}

class ProjectionQuality : public Node {
 public:
  explicit ProjectionQuality(const NodeSetup& setup) : layer_(setup.id, inputLayers(setup)) {
    layer_.setWeighting(setup.parameters.real("quality"), setup.parameters.boolean("resolution"));
  }

  Layer* layer() override { return &layer_; }

 private:
  ProjectionQualityLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "composite.projection_quality";
  type.category = NodeCategory::Compositor;
  type.summary = "Blends layers of one kind by how well each is sampled where it lands (isotropy and resolution)";
  type.inputs = {{.name = "layers", .type = PortType::Layer, .list = true,
                  .doc = "layers of one kind in any projections: a global map and polar caps, strips, insets"}};
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "quality", .type = ParameterType::Real, .defaultValue = 4.0, .minimum = 1.01, .maximum = 1000.0,
       .doc = "n of the isotropy weight 1 - |log k / log n|: texels n times longer than wide count nothing (4: the "
              "thesis finds 2 extremely aggressive, and larger n gentler on slopes seen edge on)"},
      {.name = "resolution", .type = ParameterType::Boolean, .defaultValue = true,
       .doc = "weigh by texels a pixel as well (up to one), so that the sharper of two well-shaped layers wins"},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<ProjectionQuality>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-projection-quality", "0.1.0", strata::composite::registerTypes)
