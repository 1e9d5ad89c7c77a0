// source.procedural: the demonstration planet of [Kooima 2008, ch. 4], a fractal sum of 3D simplex noise,
// as a height or colour layer computed on the GPU. It needs no data files. The plugin also registers
// source.checker (source_checker.hpp).
#include <cstdint>
#include <memory>

#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "plugin_shaders.hpp"
#include "procedural_layer.hpp"
#include "source_checker.hpp"

namespace strata::procedural {
namespace {

// The node's settings as a pipeline writes them: the planet's defaults are the model's, for a Mars-sized
// body (planet_model.hpp says why each).
struct ProceduralSettings {
  LayerKind kind = LayerKind::Color;
  std::int64_t seed = PlanetParameters{}.seed;
  double amplitude = PlanetParameters{}.amplitude;
  double wavelength = PlanetParameters{}.wavelength;
  int octaves = PlanetParameters{}.octaves;
  double contourInterval = PlanetParameters{}.contourInterval;
  double scale = 1.0;  // the true heights
};

const ParameterBindings<ProceduralSettings>& proceduralParameters() {
  using S = ProceduralSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .choice(&S::kind,
                  {.name = "kind",
                   .doc = "height: metres above the body's sphere; color: a height ramp with dark contour lines"},
                  {{"height", LayerKind::Height}, {"color", LayerKind::Color}})
          .add(&S::seed, {.name = "seed",
                          .minimum = 0.0,
                          .maximum = 2147483647.0,
                          .doc = "which planet: every seed gives an unrelated one"})
          .add(&S::amplitude, {.name = "amplitude",
                               .minimum = 1.0,
                               .maximum = 1.0e6,
                               .units = "m",
                               .doc = "heights stay within +-amplitude; a typical one is a fifth of it"})
          .add(&S::wavelength, {.name = "wavelength",
                                .minimum = 1.0,
                                .maximum = 1.0e8,
                                .units = "m",
                                .doc = "size of the largest features"})
          .add(&S::octaves,
               {.name = "octaves",
                .minimum = 1.0,
                .maximum = 24.0,
                .doc =
                    "octaves summed, each half the size of the one before (fewer are summed where samples are coarse)"})
          .add(&S::contourInterval, {.name = "contour_interval",
                                     .minimum = 1.0,
                                     .maximum = 1.0e6,
                                     .units = "m",
                                     .doc = "color: height between contour lines"})
          .add(&S::scale,
               {.name = "scale",
                .minimum = 0.0,
                .maximum = 1.0e6,
                .doc = "height: multiplies the heights handed on (vertical exaggeration); colours keep true heights"});
  return bindings;
}

PlanetParameters planetOf(const ProceduralSettings& settings) {
  PlanetParameters planet;
  planet.seed = std::uint32_t(settings.seed);
  planet.amplitude = settings.amplitude;
  planet.wavelength = settings.wavelength;
  planet.octaves = settings.octaves;
  planet.contourInterval = settings.contourInterval;
  return planet;
}

class ProceduralSource : public Node {
 public:
  explicit ProceduralSource(const NodeSetup& setup)
      : ProceduralSource(setup, proceduralParameters().read(setup.parameters)) {}

  // Sampled relative to the point below the eye, so that its fine octaves keep their digits up close.
  void prepare(const FrameState& frame) override { layer_.setReference(frame.view.reference); }

  Layer* layer() override { return &layer_; }

 private:
  ProceduralSource(const NodeSetup& setup, const ProceduralSettings& settings)
      : layer_(setup.id, settings.kind, planetOf(settings), setup.body->radius, settings.scale) {}

  ProceduralLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "source.procedural";
  type.category = NodeCategory::Source;
  type.summary = "A procedural planet of 3D simplex noise (Kooima 2008's demonstration planet), as heights or colours";
  type.output = PortType::Layer;
  type.parameters = proceduralParameters().declarations();
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
