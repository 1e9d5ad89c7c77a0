// composite.relief: shaded relief of any height layer, grey or multiplied over a surface layer, lit by a light
// at an azimuth and altitude ([Kooima 2008, §1.1], relief shading).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/sun.hpp>

#include "plugin_shaders.hpp"
#include "relief_layer.hpp"

namespace strata::composite {
namespace {

std::string rampProblem(const std::vector<double>& stops) {
  if (stops.size() % 4 != 0 || stops.size() < 8 || stops.size() > 4 * ReliefLayer::kRampStops)
    return "the ramp has " + std::to_string(stops.size()) + " numbers, not 2 to 8 stops of 4";
  for (std::size_t i = 0; i < stops.size(); i += 4) {
    if (i > 0 && stops[i] <= stops[i - 4]) return "the ramp's values do not rise at stop " + std::to_string(i / 4 + 1);
    for (std::size_t c = 1; c < 4; ++c)
      if (stops[i + c] < 0.0 || stops[i + c] > 1.0)
        return "a colour of stop " + std::to_string(i / 4 + 1) + " lies outside [0, 1]";
  }
  return {};
}

// The node's settings as a pipeline writes them, each default's reason beside it.
struct ReliefSettings {
  double azimuth = 315.0;  // light from the north-west, the cartographic convention, under which relief reads as raised
  double altitude = 45.0;  // the usual hillshade default: flat ground at cos 45 = 0.71, slopes shown both ways
  bool sun = false;        // a hillshade's light, the same over the whole map, as cartographers draw relief
  double exaggeration = 1.0;      // the true relief; raise it to see gentle slopes on a planet's scale
  bool multiply = true;           // shaded imagery, the common use; alone shows the shade even where a surface is given
  bool multidirectional = false;  // the one light a reader expects; four show relief facing any way, as from orbit
  ReliefLayer::Output output = ReliefLayer::Output::Shade;  // what relief shading is for; the others are data
  bool normalised = false;  // the hillshade as cartographers know it, flat ground at sin(altitude)
  ReliefLayer::Tint tint = ReliefLayer::Tint::None;  // the shade alone reads as relief; a tint is a choice
  // A hypsometric ramp for Earth-like elevations: sea blue, lowland green, upland tan, summits white.
  std::vector<double> tintRamp{-4000, 0.1, 0.3, 0.6, 0, 0.3, 0.55, 0.3, 2000, 0.75, 0.65, 0.45, 5000, 1, 1, 1};
};

// Every parameter is live: the light, the exaggeration, the mode and the tint change the next frame.
const ParameterBindings<ReliefSettings>& reliefParameters() {
  using S = ReliefSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::azimuth, {.name = "azimuth",
                             .minimum = 0.0,
                             .maximum = 360.0,
                             .units = "deg",
                             .doc = "direction the light comes from, clockwise from north",
                             .live = true})
          .add(&S::altitude, {.name = "altitude",
                              .minimum = 0.0,
                              .maximum = 90.0,
                              .units = "deg",
                              .doc = "height of the light above the horizon",
                              .live = true})
          .choice(&S::sun,
                  {.name = "light",
                   .doc = "azimuth: one light at azimuth and altitude over every point (a hillshade); sun: the "
                          "scene's sun as it stands over each point, dark where it has set",
                   .live = true},
                  {{"azimuth", false}, {"sun", true}})
          .add(&S::exaggeration, {.name = "exaggeration",
                                  .minimum = 0.0,
                                  .maximum = 1.0e4,
                                  .doc = "factor on the heights' slopes before shading (vertical exaggeration)",
                                  .live = true})
          .choice(&S::multiply,
                  {.name = "blend",
                   .doc = "multiply: the surface's colour times the shade; alone: the grey shade",
                   .live = true},
                  {{"multiply", true}, {"alone", false}})
          .choice(&S::multidirectional,
                  {.name = "mode",
                   .doc = "single: one light at azimuth; multidirectional: four at 225 to 360 degrees, weighted by "
                          "the aspect (Mark 1992), at altitude",
                   .live = true},
                  {{"single", false}, {"multidirectional", true}})
          .choice(&S::output,
                  {.name = "output",
                   .doc = "shade: the Lambertian shade; slope: the slope's angle over 90 degrees (0 flat, 1 "
                          "vertical); aspect: the downslope direction clockwise from north over 360 degrees",
                   .live = true},
                  {{"shade", ReliefLayer::Output::Shade},
                   {"slope", ReliefLayer::Output::Slope},
                   {"aspect", ReliefLayer::Output::Aspect}})
          .add(&S::normalised, {.name = "normalise",
                                .doc = "divide the shade by flat ground's, sin(altitude), so that multiplied imagery "
                                       "keeps its colour on flat ground and slopes toward the light brighten it (up "
                                       "to white)",
                                .live = true})
          .choice(&S::tint,
                  {.name = "tint",
                   .doc = "colours the value by tint_ramp: by elevation (m) or by slope (deg); none: grey",
                   .live = true},
                  {{"none", ReliefLayer::Tint::None},
                   {"elevation", ReliefLayer::Tint::Elevation},
                   {"slope", ReliefLayer::Tint::Slope}})
          .add(&S::tintRamp, {.name = "tint_ramp",
                              .doc = "2 to 8 stops of value (m, or deg of slope), red, green, blue (sRGB, 0 to 1), "
                                     "values rising; blended linearly in scene-linear light, held beyond the ends",
                              .live = true});
  return bindings;
}

ReliefLayer::Ramp tintOf(const ReliefSettings& settings, const ParameterSet& parameters) {
  if (settings.tint == ReliefLayer::Tint::None) return {};
  if (const std::string problem = rampProblem(settings.tintRamp); !problem.empty())
    throw Error(
        reliefParameters().where(parameters, &ReliefSettings::tintRamp), problem,
        "give stops of value, red, green, blue (sRGB, 0 to 1), values rising, e.g. [0, 0, 0.4, 0, 3000, 1, 1, 1]");
  return {settings.tint, settings.tintRamp};
}

// Throws strata::Error at `light` where it asks for a sun the scene does not place (`sunKnown`), or for the
// sun together with the multidirectional mode's fixed lights.
void checkSun(const ReliefSettings& settings, const ParameterSet& parameters, bool sunKnown) {
  if (!settings.sun) return;
  const SourceLocation& where = reliefParameters().where(parameters, &ReliefSettings::sun);
  if (!sunKnown) throw sunUnknown(where, "light: sun");
  if (settings.multidirectional)
    throw Error(where, "light: sun has one light, the sun; mode: multidirectional has four of its own",
                "set mode: single, or light: azimuth");
}

ReliefLayer::Lighting lightingOf(const ParameterSet& parameters, bool sunKnown) {
  const ReliefSettings settings = reliefParameters().read(parameters);
  checkSun(settings, parameters, sunKnown);
  return {settings.azimuth,
          settings.altitude,
          settings.exaggeration,
          settings.multiply,
          settings.multidirectional,
          settings.output,
          tintOf(settings, parameters),
          settings.normalised,
          settings.sun};
}

const Layer* surfaceOf(const NodeSetup& setup) {
  Node* surface = setup.input("surface");
  return surface ? surface->layer() : nullptr;
}

class Relief : public Node {
 public:
  explicit Relief(const NodeSetup& setup)
      : sunKnown_(setup.sun.has_value()),
        layer_(setup.id, *setup.input("height")->layer(), surfaceOf(setup), lightingOf(setup.parameters, sunKnown_),
               setup.body->radius) {}

  Layer* layer() override { return &layer_; }
  void prepare(const FrameState& frame) override {
    if (frame.sun) layer_.setSun(sunDirection(*frame.sun));
  }
  void update(const ParameterSet& parameters) override { layer_.relight(lightingOf(parameters, sunKnown_)); }

 private:
  bool sunKnown_;  // whether the scene places the sun (NodeSetup::sun): light: sun needs it
  ReliefLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.relief";
  type.category = NodeCategory::Compositor;
  type.summary =
      "Shaded relief of a height layer, grey or multiplied over a colour layer, lit at an azimuth and altitude or by "
      "the sun";
  type.inputs = {{.name = "height",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Height},
                  .doc = "the heights to shade: any height layer, composed ones included"},
                 {.name = "surface",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Color},
                  .optional = true,
                  .doc = "a colour layer the shade multiplies (blend: multiply); without one the shade is grey"}};
  type.output = PortType::Layer;
  type.parameters = reliefParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<Relief>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-relief", "0.1.0", strata::composite::registerTypes)
