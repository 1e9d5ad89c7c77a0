// composite.projection_quality: layers of one kind, in any projections, blended sample by sample by how well
// each is sampled where it lands [Kooima 2008, §4.1], so that a global map and
// polar caps compose into one layer sharp at the equator and at the poles, with no seam where they cross.
#include <memory>
#include <numbers>
#include <vector>

#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "plugin_shaders.hpp"
#include "projection_quality_layer.hpp"

namespace strata::composite {
namespace {

using Method = ProjectionQualityLayer::Method;

constexpr double kDegree = std::numbers::pi / 180.0;  // radians per degree

// The node's settings as a pipeline writes them, each default's reason beside it.
struct ProjectionQualitySettings {
  // Isotropy: it weighs layers of any projection, procedural ones included ([Kooima 2008, §4.1.2] calls it the
  // general method); latitude needs every layer to be a cylindrical map or a polar cap.
  Method method = Method::Isotropy;
  double quality = 4.0;    // the thesis finds 2 extremely aggressive, and larger n gentler on slopes seen edge on
  bool resolution = true;  // the sharper of two well-shaped layers wins
  // 50 to 70: a longitude/latitude map's texels are 1.6 times wider than tall at 50 degrees and 2.9 times at
  // 70 (1 / cos), while a polar stereographic cap's are square everywhere and, true to scale at its pole,
  // at most 13% larger at 50 degrees. [Kooima 2008, §4.1.2] gives its method 1 no formula and no band
  // (docs/references.md, Errata).
  std::vector<double> band{50.0, 70.0};
};

const ParameterBindings<ProjectionQualitySettings>& projectionQualityParameters() {
  using S = ProjectionQualitySettings;
  static const auto bindings =
      ParameterBindings<S>()
          .choice(&S::method,
                  {.name = "method",
                   .doc = "isotropy: by the shape of each layer's texels where they land (thesis method 2); "
                          "latitude: a longitude/latitude map fades into polar caps across `band` (method 1, its "
                          "cubic falloff)"},
                  {{"isotropy", Method::Isotropy}, {"latitude", Method::Latitude}})
          .add(&S::quality, {.name = "quality",
                             .minimum = 1.01,
                             .maximum = 1000.0,
                             .doc = "isotropy method: n of the weight 1 - |log k / log n|: texels n times longer "
                                    "than wide count nothing (4: the thesis finds 2 extremely aggressive, and "
                                    "larger n gentler on slopes seen edge on)"})
          .add(&S::resolution, {.name = "resolution",
                                .doc = "isotropy method: weigh by texels a pixel as well (up to one), so that the "
                                       "sharper of two well-shaped layers wins; the latitude method's weights "
                                       "depend on the place alone, not the view"})
          .add(&S::band, {.name = "band",
                          .minimum = 0.0,
                          .maximum = 90.0,
                          .units = "deg",
                          .doc = "latitude method: the |latitude| where the map starts to fade (inner) and is gone "
                                 "(outer), the polar caps fading in across it as their complement",
                          .count = 2});
  return bindings;
}

// The band's inner and outer latitude in radians; the declaration has kept both within [0, 90] degrees.
glm::dvec2 bandOf(const ProjectionQualitySettings& settings, const ParameterSet& parameters) {
  const std::vector<double>& band = settings.band;
  if (!(0.0 < band[0] && band[0] < band[1] && band[1] < 90.0))
    throw Error(projectionQualityParameters().where(parameters, &ProjectionQualitySettings::band),
                "the band " + formatValue(band) +
                    " is not an inner and a greater outer latitude strictly between 0 and 90 degrees",
                "give band: [inner, outer] with 0 < inner < outer < 90, e.g. [50, 70]");
  return glm::dvec2(band[0], band[1]) * kDegree;
}

ProjectionQualityLayer::Weighting weightingOf(const ParameterSet& parameters) {
  const ProjectionQualitySettings settings = projectionQualityParameters().read(parameters);
  return {.method = settings.method,
          .quality = settings.quality,
          .resolution = settings.resolution,
          .band = bandOf(settings, parameters)};
}

// The latitude method weighs each layer by the region its projection samples best, which a raster knows once
// its node has placed it (createResources, upstream of this node's).
void requireAspects(const std::vector<const Layer*>& layers, const SourceLocation& where) {
  for (std::size_t i = 0; i < layers.size(); ++i)
    if (aspectOf(*layers[i]) == ProjectionAspect::Other)
      throw Error(
          where,
          "method: latitude weighs each layer by the region its projection samples best, but layer " +
              std::to_string(i + 1) +
              " of its `layers` is in no projection that samples the equator or a "
              "pole best (it is procedural or composed, HEALPix, or an oblique or transverse aspect)",
          "use method: isotropy, which weighs layers of any projection by the shape of their texels; or "
          "give only longitude/latitude maps and polar caps (polar stereographic, or orthographic or perspective "
          "centred on a pole)");
}

class ProjectionQuality : public Node {
 public:
  explicit ProjectionQuality(const NodeSetup& setup)
      : methodWhere_(projectionQualityParameters().where(setup.parameters, &ProjectionQualitySettings::method)),
        inputs_(layersOfOneKind(setup.inputList("layers"), "layers", setup.where)),
        weighting_(weightingOf(setup.parameters)),
        layer_(setup.id, inputs_) {
    layer_.setWeighting(weighting_);
  }

  void createResources(GpuContext&) override {
    if (weighting_.method == Method::Latitude) requireAspects(inputs_, methodWhere_);
  }

  Layer* layer() override { return &layer_; }

 private:
  SourceLocation methodWhere_;
  std::vector<const Layer*> inputs_;
  ProjectionQualityLayer::Weighting weighting_;
  ProjectionQualityLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.projection_quality";
  type.category = NodeCategory::Compositor;
  type.summary = "Blends layers of one kind by how well each is sampled where it lands (isotropy, or latitude)";
  type.inputs = {{.name = "layers",
                  .type = PortType::Layer,
                  .list = true,
                  .doc = "layers of one kind in any projections: a global map and polar caps, strips, insets"}};
  type.output = PortType::Layer;
  type.parameters = projectionQualityParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<ProjectionQuality>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-projection-quality", "0.1.0", strata::composite::registerTypes)
