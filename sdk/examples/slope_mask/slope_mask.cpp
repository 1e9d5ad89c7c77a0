// composite.slope_mask: paints the ground steeper than a threshold over a colour layer, from any height
// layer (a landing-site or trafficability map: where a lander or a rover may not go). An example of a
// compositor built out of tree against an installed Strata SDK: a layer whose GLSL samples two input layers
// and combines them, with every parameter a uniform that the viewer's controls change live.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include <strata/body.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/height_slopes.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/srgb.hpp>

#include "plugin_shaders.hpp"

namespace slope_mask {
namespace {

// The node's settings as a pipeline writes them, each default's reason beside it.
struct SlopeMaskSettings {
  // 15: the order of the limits Mars landing sites were chosen by (InSight's was 15), a first cut of a site map
  double threshold = 15.0;
  // A saturated magenta: no terrain or imagery has it, so painted ground reads at a glance
  std::vector<double> colour{1.0, 0.0, 1.0};
  // 0.6: the paint dominates, yet the imagery below still shows what makes the ground steep
  double opacity = 0.6;
};

// The one declaration of each parameter, from which the core derives validation, error messages,
// `strata plugins --describe` and docs/reference/. Every parameter is a uniform (.live): changing one
// redraws the next frame with no program rebuilt.
const strata::ParameterBindings<SlopeMaskSettings>& slopeMaskParameters() {
  using S = SlopeMaskSettings;
  static const auto bindings =
      strata::ParameterBindings<S>()
          .add(&S::threshold,
               {.name = "threshold",
                .minimum = 0.0,
                .maximum = 90.0,
                .units = "deg",
                .doc = "ground steeper than this is painted; slopes are measured over a pixel's footprint",
                .live = true})
          .add(&S::colour, {.name = "colour",
                            .minimum = 0.0,
                            .maximum = 1.0,
                            .doc = "the paint, as sRGB red, green, blue, each from 0 to 1",
                            .count = 3,
                            .live = true})
          .add(&S::opacity,
               {.name = "opacity",
                .minimum = 0.0,
                .maximum = 1.0,
                .doc =
                    "the paint's share over the surface on steep ground: 0 shows the surface alone, 1 the paint alone",
                .live = true});
  return bindings;
}

// What to paint, in the units the GLSL takes; all of it reaches the GPU as uniforms.
struct MaskStyle {
  double threshold = 0.0;  // rad: slopes steeper than this are painted
  glm::vec3 colour{};      // scene-linear RGB, as layers' values are
  double opacity = 0.0;    // the paint's share over the surface, 0 to 1
};

MaskStyle styleOf(const strata::ParameterSet& parameters) {
  const SlopeMaskSettings settings = slopeMaskParameters().read(parameters);
  const std::vector<double>& colour = settings.colour;  // exactly 3: the declaration's count
  return {settings.threshold * std::numbers::pi / 180.0, strata::srgbToSceneLinear(colour[0], colour[1], colour[2]),
          settings.opacity};
}

// The layer: its GLSL samples the surface, and the heights at a point with their slopes
// (strata::heightSlopesGlsl), then lays the paint over the surface where the slope
// is steeper than the threshold, weighted by the heights' coverage (no data, no paint).
class SlopeMaskLayer : public strata::Layer {
 public:
  SlopeMaskLayer(const std::string& nodeId, const strata::Layer& height, const strata::Layer& surface, MaskStyle style,
                 double radius)
      : name_("layer_" + strata::glslIdentifier(nodeId)),
        height_(height),
        surface_(surface),
        style_(style),
        radius_(radius) {}

  strata::LayerKind kind() const override { return strata::LayerKind::Color; }
  std::string samplingFunction() const override { return name_; }

  // Every name is prefixed by the node's, so that two slope masks in one program do not clash; the paint
  // itself is slope_mask.glsl's, which strata_add_plugin embedded in this module.
  std::string glsl() const override {
    const std::string& p = name_;
    const std::string slopes = strata::heightSlopesGlsl(p + "_slopes", height_, p + "_radius");
    return height_.glslOnce() + surface_.glslOnce() + "#include \"slope_mask/slope_mask.glsl\"\n" +                 //
           "uniform float " + p + "_radius, " + p + "_threshold, " + p + "_opacity;\n" +                            //
           "uniform vec3 " + p + "_colour;\n" + slopes +                                                            //
           "vec4 " + p + "(SurfacePoint p) {\n" +                                                                   //
           "  vec4 height = " + p + "_slopes(p);\n" +                                                               //
           "  return slopeMaskOver(" + surface_.samplingFunction() + "(p), height, slopeAngle(height.gb, 1.0), " +  //
           p + "_threshold, " + p + "_colour, " + p + "_opacity);\n}\n";
  }

  void bind(strata::ShaderProgram& program, strata::TextureUnits& units) const override {
    height_.bind(program, units);
    surface_.bind(program, units);
    program.set(name_ + "_radius", static_cast<float>(radius_));
    program.set(name_ + "_threshold", static_cast<float>(style_.threshold));
    program.set(name_ + "_colour", style_.colour);
    program.set(name_ + "_opacity", static_cast<float>(style_.opacity));
  }

  // A compositor wants what its inputs hold as much as it is wanted itself (paged inputs load for it).
  void setPageDemand(strata::PageDemand demand) const override {
    height_.setPageDemand(demand);
    surface_.setPageDemand(demand);
  }
  // Its values change as its inputs' do (pages arriving beneath it).
  std::uint64_t revision() const override { return height_.revision() + surface_.revision(); }

  void restyle(MaskStyle style) { style_ = style; }  // for the next bind(): uniforms only

 private:
  std::string name_;
  const strata::Layer& height_;
  const strata::Layer& surface_;
  MaskStyle style_;
  double radius_;  // m, the body's: slopes are rise over distance along the ground
};

// The node: its inputs' layers exist when it is made; update() takes live parameter changes between frames.
class SlopeMask : public strata::Node {
 public:
  explicit SlopeMask(const strata::NodeSetup& setup)
      : layer_(setup.id, *setup.input("height")->layer(), *setup.input("surface")->layer(), styleOf(setup.parameters),
               setup.body->radius) {}

  strata::Layer* layer() override { return &layer_; }
  void update(const strata::ParameterSet& parameters) override { layer_.restyle(styleOf(parameters)); }

 private:
  SlopeMaskLayer layer_;
};

// The node type: its name, its inputs and output, its parameters (declared above) and how to make it.
strata::NodeTypeDeclaration declaration() {
  using strata::LayerKind, strata::PortType;
  strata::NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // slope_mask.glsl, embedded by strata_add_plugin
  type.type = "composite.slope_mask";
  type.category = strata::NodeCategory::Compositor;
  type.summary = "Paints ground steeper than a threshold over a colour layer, from any height layer";
  type.inputs = {{.name = "height",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Height},
                  .doc = "the heights whose slopes are measured: any height layer, composed ones included"},
                 {.name = "surface",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Color},
                  .doc = "the colour layer painted over; it shows unchanged where the ground is not steep"}};
  type.output = PortType::Layer;
  type.parameters = slopeMaskParameters().declarations();
  type.create = [](const strata::NodeSetup& setup) { return std::make_unique<SlopeMask>(setup); };
  return type;
}

void registerTypes(strata::PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace slope_mask

STRATA_PLUGIN("slope_mask", "0.1.0", slope_mask::registerTypes)
