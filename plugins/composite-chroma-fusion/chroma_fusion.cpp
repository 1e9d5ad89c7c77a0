// composite.chroma_fusion: a high-resolution luminance layer (HiRISE-like panchromatic) and a low-resolution
// colour layer (Viking-like) fused into one high-resolution colour layer, chroma from the one and luminance
// from the other in an opponent space [Kooima 2008, §1.1, §3.4.3].
#include <memory>
#include <string>

#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "chroma_fusion_layer.hpp"
#include "plugin_shaders.hpp"

namespace strata::composite {
namespace {

using Space = ChromaFusionLayer::Space;
using Matching = ChromaFusionLayer::Matching;

// The node's settings as a pipeline writes them, each default's reason beside it.
struct ChromaFusionSettings {
  // Lab: its lightness depends on luminance alone, so a panchromatic measurement sets it exactly, and its chroma
  // is perceptually even.
  Space space = Space::Lab;
  double strength = 1.0;  // the fusion the node is for; lower it to fade the luminance's detail in and out
  // Detail: two data sets seldom agree in absolute brightness (sensor, exposure, illumination), and the colour's
  // own brightness is what keeps its hue.
  Matching matching = Matching::Detail;
};

// Every parameter is live: the space, the strength and the matching change the next frame.
const ParameterBindings<ChromaFusionSettings>& chromaFusionParameters() {
  using S = ChromaFusionSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .choice(&S::space,
                  {.name = "space",
                   .doc = "the opponent space whose chroma is kept: lab (CIE L*a*b*, D65) or ycbcr (BT.709 Y'CbCr of "
                          "the sRGB-encoded values, as image files hold it)",
                   .live = true},
                  {{"lab", Space::Lab}, {"ycbcr", Space::YCbCr}})
          .add(&S::strength,
               {.name = "strength",
                .minimum = 0.0,
                .maximum = 1.0,
                .doc = "how far the lightness moves to the fused luminance: 0 the colour layer alone, 1 full fusion",
                .live = true})
          .choice(&S::matching,
                  {.name = "matching",
                   .doc = "detail: the colour layer's luminance times the luminance layer's ratio to its own "
                          "low-pass at the colour layer's resolution; none: the luminance layer's luminance as it is",
                   .live = true},
                  {{"detail", Matching::Detail}, {"none", Matching::None}});
  return bindings;
}

// One node on both ports would paste its layer's GLSL into the program twice, which does not compile; and
// fusing an image with itself changes nothing.
const Layer& colourOf(const NodeSetup& setup) {
  if (setup.input("luminance") == setup.input("colour"))
    throw Error(setup.where, "the luminance and the colour are the same node",
                "give the high-resolution luminance (or colour) layer as `luminance`, the low-resolution colour "
                "layer as `colour`");
  return *setup.input("colour")->layer();
}

ChromaFusionLayer::Fusion fusionOf(const ParameterSet& parameters, const Layer& colour) {
  const ChromaFusionSettings settings = chromaFusionParameters().read(parameters);
  const ChromaFusionLayer::Fusion fusion{settings.space, settings.strength, settings.matching};
  if (fusion.matching == Matching::Detail && texelStepsFunctionOf(colour).empty())
    throw Error(chromaFusionParameters().where(parameters, &ChromaFusionSettings::matching),
                "the colour layer has no texels (procedural, or a composite that offers none), whose size the "
                "luminance's detail is measured against",
                "give a raster colour layer (source.gdal), or matching: none to take the luminance as it is");
  return fusion;
}

class ChromaFusion : public Node {
 public:
  explicit ChromaFusion(const NodeSetup& setup)
      : colour_(colourOf(setup)),
        layer_(setup.id, *setup.input("luminance")->layer(), colour_, fusionOf(setup.parameters, colour_)) {}

  Layer* layer() override { return &layer_; }
  void update(const ParameterSet& parameters) override { layer_.setFusion(fusionOf(parameters, colour_)); }

 private:
  const Layer& colour_;
  ChromaFusionLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.chroma_fusion";
  type.category = NodeCategory::Compositor;
  type.summary =
      "Fuses a high-resolution luminance layer with a low-resolution colour layer: chroma from the one, "
      "luminance from the other, in CIE L*a*b* or Y'CbCr";
  type.inputs = {{.name = "luminance",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Luminance, LayerKind::Color},
                  .doc = "the high-resolution layer whose luminance the result takes: a luminance layer (its value, "
                         "scene-linear relative luminance) or a colour layer (its Rec. 709 luminance)"},
                 {.name = "colour",
                  .type = PortType::Layer,
                  .kinds = {LayerKind::Color},
                  .doc = "the low-resolution colour layer whose chroma the result takes"}};
  type.output = PortType::Layer;
  type.parameters = chromaFusionParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<ChromaFusion>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-chroma-fusion", "0.1.0", strata::composite::registerTypes)
