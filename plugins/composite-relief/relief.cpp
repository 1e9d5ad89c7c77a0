// composite.relief: shaded relief of any height layer, grey or multiplied over a surface layer, lit by a light
// at an azimuth and altitude (seed 000 section 1.1, relief shading; digest 000 section 6).
#include <memory>

#include <strata/node.hpp>
#include <strata/node_type.hpp>
#include <strata/plugin.hpp>

#include "relief_layer.hpp"

namespace strata::composite {
namespace {

ReliefLayer::Output outputOf(const std::string& output) {
  if (output == "slope") return ReliefLayer::Output::Slope;
  return output == "aspect" ? ReliefLayer::Output::Aspect : ReliefLayer::Output::Shade;
}

ReliefLayer::Lighting lightingOf(const NodeSetup& setup) {
  const ParameterSet& parameters = setup.parameters;
  return {parameters.real("azimuth"), parameters.real("altitude"), parameters.real("exaggeration"),
          parameters.string("blend") == "multiply", parameters.string("mode") == "multidirectional",
          outputOf(parameters.string("output"))};
}

const Layer* surfaceOf(const NodeSetup& setup) {
  Node* surface = setup.input("surface");
  return surface ? surface->layer() : nullptr;
}

class Relief : public Node {
 public:
  explicit Relief(const NodeSetup& setup)
      : layer_(setup.id, *setup.input("height")->layer(), surfaceOf(setup), lightingOf(setup), setup.body->radius) {}

  Layer* layer() override { return &layer_; }

 private:
  ReliefLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "composite.relief";
  type.category = NodeCategory::Compositor;
  type.summary = "Shaded relief of a height layer, grey or multiplied over a colour layer, lit at an azimuth and altitude";
  type.inputs = {{.name = "height", .type = PortType::Layer, .kinds = {LayerKind::Height},
                  .doc = "the heights to shade: any height layer, composed ones included"},
                 {.name = "surface", .type = PortType::Layer, .kinds = {LayerKind::Color}, .optional = true,
                  .doc = "a colour layer the shade multiplies (blend: multiply); without one the shade is grey"}};
  type.output = PortType::Layer;
  type.parameters = {
      // 315: light from the north-west, the cartographic convention, under which relief reads as raised
      {.name = "azimuth", .type = ParameterType::Real, .defaultValue = 315.0, .minimum = 0.0, .maximum = 360.0,
       .units = "deg", .doc = "direction the light comes from, clockwise from north"},
      // 45: the usual hillshade default, which leaves flat ground at cos 45 = 0.71 and shows slopes both ways
      {.name = "altitude", .type = ParameterType::Real, .defaultValue = 45.0, .minimum = 0.0, .maximum = 90.0,
       .units = "deg", .doc = "height of the light above the horizon"},
      // 1: the true relief; raise it to see gentle slopes on a planet's scale
      {.name = "exaggeration", .type = ParameterType::Real, .defaultValue = 1.0, .minimum = 0.0, .maximum = 1.0e4,
       .doc = "factor on the heights' slopes before shading (vertical exaggeration)"},
      // multiply: shaded imagery, the common use; alone shows the shade even where a surface is given
      {.name = "blend", .type = ParameterType::Choice, .defaultValue = std::string("multiply"),
       .doc = "multiply: the surface's colour times the shade; alone: the grey shade",
       .choices = {"multiply", "alone"}},
      // single: the one light a reader expects; multidirectional shows relief facing any way, as from orbit
      {.name = "mode", .type = ParameterType::Choice, .defaultValue = std::string("single"),
       .doc = "single: one light at azimuth; multidirectional: four at 225 to 360 degrees, weighted by the aspect "
              "(Mark 1992), at altitude",
       .choices = {"single", "multidirectional"}},
      // shade: what relief shading is for; the others are the same gradient, as data
      {.name = "output", .type = ParameterType::Choice, .defaultValue = std::string("shade"),
       .doc = "shade: the Lambertian shade; slope: its angle over 90 degrees (0 flat, 1 vertical); aspect: the "
              "downslope direction clockwise from north over 360 degrees",
       .choices = {"shade", "slope", "aspect"}},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<Relief>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-relief", "0.1.0", strata::composite::registerTypes)
