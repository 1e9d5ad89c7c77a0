// source.procedural: the demonstration planet of [Kooima 2008, ch. 4], a fractal sum of 3D simplex noise,
// as a height or colour layer computed on the GPU. It needs no data files. The plugin also registers
// source.checker (source_checker.hpp).
#include <cstdint>
#include <memory>

#include <strata/plugin.hpp>

#include "plugin_shaders.hpp"
#include "procedural_layer.hpp"
#include "source_checker.hpp"

namespace strata::procedural {
namespace {

PlanetParameters planetOf(const ParameterSet& parameters) {
  PlanetParameters planet;
  planet.seed = std::uint32_t(parameters.integer("seed"));
  planet.amplitude = parameters.real("amplitude");
  planet.wavelength = parameters.real("wavelength");
  planet.octaves = int(parameters.integer("octaves"));
  planet.contourInterval = parameters.real("contour_interval");
  return planet;
}

class ProceduralSource : public Node {
 public:
  explicit ProceduralSource(const NodeSetup& setup)
      : layer_(setup.id, setup.parameters.string("kind") == "height" ? LayerKind::Height : LayerKind::Color,
               planetOf(setup.parameters), setup.body->radius, setup.parameters.real("scale")) {}

  // Sampled relative to the point below the eye, so that its fine octaves keep their digits up close.
  void prepare(const FrameState& frame) override { layer_.setReference(frame.view.reference); }

  Layer* layer() override { return &layer_; }

 private:
  ProceduralLayer layer_;
};

NodeTypeDeclaration declaration() {
  const PlanetParameters defaults;
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "source.procedural";
  type.category = NodeCategory::Source;
  type.summary = "A procedural planet of 3D simplex noise (Kooima 2008's demonstration planet), as heights or colours";
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "kind",
       .type = ParameterType::Choice,
       .defaultValue = std::string("color"),
       .doc = "height: metres above the body's sphere; color: a height ramp with dark contour lines",
       .choices = {"height", "color"}},
      {.name = "seed",
       .type = ParameterType::Integer,
       .defaultValue = std::int64_t(defaults.seed),
       .minimum = 0.0,
       .maximum = 2147483647.0,
       .doc = "which planet: every seed gives an unrelated one"},
      {.name = "amplitude",
       .type = ParameterType::Real,
       .defaultValue = defaults.amplitude,
       .minimum = 1.0,
       .maximum = 1.0e6,
       .units = "m",
       .doc = "heights stay within +-amplitude; a typical one is a fifth of it"},
      {.name = "wavelength",
       .type = ParameterType::Real,
       .defaultValue = defaults.wavelength,
       .minimum = 1.0,
       .maximum = 1.0e8,
       .units = "m",
       .doc = "size of the largest features"},
      {.name = "octaves",
       .type = ParameterType::Integer,
       .defaultValue = std::int64_t(defaults.octaves),
       .minimum = 1.0,
       .maximum = 24.0,
       .doc = "octaves summed, each half the size of the one before (fewer are summed where samples are coarse)"},
      {.name = "contour_interval",
       .type = ParameterType::Real,
       .defaultValue = defaults.contourInterval,
       .minimum = 1.0,
       .maximum = 1.0e6,
       .units = "m",
       .doc = "color: height between contour lines"},
      {.name = "scale",
       .type = ParameterType::Real,
       .defaultValue = 1.0,
       .minimum = 0.0,
       .maximum = 1.0e6,
       .doc = "height: multiplies the heights handed on (vertical exaggeration); colours keep true heights"},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<ProceduralSource>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) {
  registrar.add(declaration());
  registrar.add(checkerDeclaration());
}

}  // namespace
}  // namespace strata::procedural

STRATA_PLUGIN("source-procedural", "0.1.0", strata::procedural::registerTypes)
