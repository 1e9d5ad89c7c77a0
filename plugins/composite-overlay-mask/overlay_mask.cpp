// composite.overlay_mask: a local layer (a strip along a ground track, a crater map, a LIDAR patch) laid over a
// base layer of any resolution where it has data and an optional mask allows, with a hard or feathered edge
// [Kooima 2008, §4.2].
#include <memory>

#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "overlay_mask_layer.hpp"
#include "plugin_shaders.hpp"

namespace strata::composite {
namespace {

// The node's settings as a pipeline writes them.
struct OverlayMaskSettings {
  double feather = 0.0;  // a hard edge
  bool metres = false;   // the overlay's texels, so the fade follows its resolution
};

const ParameterBindings<OverlayMaskSettings>& overlayMaskParameters() {
  using S = OverlayMaskSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::feather,
               {.name = "feather",
                .minimum = 0.0,
                .maximum = 1.0e7,
                .doc = "width over which the overlay fades in from its edge, in feather_units; 0: a hard edge"})
          .choice(&S::metres,
                  {.name = "feather_units",
                   .doc = "texels: the overlay's own, so the fade follows its resolution; metres: along the ground"},
                  {{"texels", false}, {"metres", true}});
  return bindings;
}

// One node on two of the ports would paste its layer's GLSL into the program twice, which does not compile.
void refuseRepeatedInputs(const NodeSetup& setup) {
  const Node *base = setup.input("base"), *overlay = setup.input("overlay"), *mask = setup.input("mask");
  if (base == overlay)
    throw Error(setup.where, "the base and the overlay are the same node", "lay another layer over the base");
  if (mask == base || mask == overlay)
    throw Error(setup.where, std::string("the mask is also the ") + (mask == base ? "base" : "overlay"),
                "give the mask a node of its own (source.gdal, kind: mask); the overlay's own coverage (its "
                "nodata, its alpha) limits it without one");
}

// The overlay, once it is known to be of the base's kind.
const Layer& overlayOf(const NodeSetup& setup) {
  refuseRepeatedInputs(setup);
  const Layer &base = *setup.input("base")->layer(), &overlay = *setup.input("overlay")->layer();
  if (base.kind() != overlay.kind())
    throw Error(setup.where,
                "the overlay is a " + std::string(toString(overlay.kind())) + " layer, the base a " +
                    toString(base.kind()) + " layer",
                "lay heights over heights, colours over colours");
  return overlay;
}

// The mask, where one is given: any layer, whose value says where the overlay shows.
const Layer* maskOf(const NodeSetup& setup) {
  Node* mask = setup.input("mask");
  return mask ? mask->layer() : nullptr;
}

OverlayMaskLayer::Edge edgeOf(const NodeSetup& setup, const Layer& overlay) {
  const OverlayMaskSettings settings = overlayMaskParameters().read(setup.parameters);
  const OverlayMaskLayer::Edge edge{settings.feather, settings.metres, setup.body->radius};
  if (edge.feather > 0.0 && texelStepsFunctionOf(overlay).empty())
    throw Error(overlayMaskParameters().where(setup.parameters, &OverlayMaskSettings::feather),
                "the overlay has no texels to feather its edge over",
                "give a raster overlay (source.gdal), or feather: 0 for a hard edge");
  return edge;
}

class OverlayMask : public Node {
 public:
  explicit OverlayMask(const NodeSetup& setup)
      : layer_(setup.id, *setup.input("base")->layer(), overlayOf(setup), maskOf(setup),
               edgeOf(setup, overlayOf(setup))) {}

  Layer* layer() override { return &layer_; }

 private:
  OverlayMaskLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.overlay_mask";
  type.category = NodeCategory::Compositor;
  type.summary =
      "Lays a local layer over a base layer where it has data (and a mask allows), with a hard or feathered edge";
  type.inputs = {{.name = "base", .type = PortType::Layer, .doc = "the layer beneath, of any resolution"},
                 {.name = "overlay",
                  .type = PortType::Layer,
                  .doc = "the local layer on top, of the same kind: where it has data (its extent, nodata, alpha)"},
                 {.name = "mask",
                  .type = PortType::Layer,
                  .optional = true,
                  .doc = "where the overlay may show: a layer whose value (0 to 1, e.g. source.gdal kind: mask, from a "
                         "raster or a vector file's polygons) times its coverage multiplies the overlay's"}};
  type.output = PortType::Layer;
  type.parameters = overlayMaskParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<OverlayMask>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-overlay-mask", "0.1.0", strata::composite::registerTypes)
