// geometry.healpix: the body tessellated as twelve HEALPix quadtrees [Westerteiger et al. 2011]. Each frame the
// nodes the view needs are chosen on the CPU in double (node_selection.hpp), then drawn from one stitched
// proxy grid that the vertex shader places with the HEALPix inverse and displaces by the height layer, into
// the same deferred texturing buffer as the other generators. docs/healpix.md explains the parts.
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <strata/gl/gpu_timer.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/surface_buffer.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/height_input.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "node_buffers.hpp"
#include "plugin_shaders.hpp"

namespace strata::healpix {
namespace {

// The node's parameters, bound to the selection's settings, whose defaults they take; the deepest level is fixed.
const ParameterBindings<SelectionSettings>& healpixParameters() {
  using S = SelectionSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::threshold, {.name = "threshold",
                               .minimum = 0.001,
                               .maximum = 10.0,
                               .doc = "vertices wanted per pixel: a node is drawn once its area on screen times this "
                                      "needs no more vertices than its grid has (0.2 is the paper's recommendation; it "
                                      "measured 0.005 to 1.0)"})
          .add(&S::gridCells, {.name = "cells",
                               .minimum = 2.0,
                               .maximum = 254.0,
                               .doc = "grid cells along a node's side, even (64: 4225 vertices a node, so a few "
                                      "hundred nodes cover a view; the paper's 254 is its data tiles' size, 16-bit "
                                      "indices)"})
          .add(&S::pixelError, {.name = "pixel_error",
                                .minimum = 0.0,
                                .maximum = 100.0,
                                .doc = "px: a node whose geometric error shows no more than this is drawn, however "
                                       "many vertices its area asks for (one pixel is what the eye cannot resolve; 0: "
                                       "the threshold alone, as the paper)"});
  return bindings;
}

SelectionSettings selectionOf(const NodeSetup& setup) {
  const SelectionSettings settings = healpixParameters().read(setup.parameters);
  if (settings.gridCells % 2 != 0)
    throw Error(healpixParameters().where(setup.parameters, &SelectionSettings::gridCells),
                "cells (" + std::to_string(settings.gridCells) + ") is odd",
                "give an even number: an edge next to a coarser node keeps every other vertex");
  return settings;
}

class HealpixGeometry : public Node, public SurfaceGeometry {
 public:
  explicit HealpixGeometry(const NodeSetup& setup)
      : heights_(setup), radius_(setup.body->radius), settings_(selectionOf(setup)) {}

  void open() override { heights_.open(); }

  void createResources(GpuContext& gpu) override {
    surface_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "geometry-healpix/healpix_surface.vert",
          gpu.shaders->expand("geometry-healpix/healpix_surface.vert", heights_.substitutions())},
         {GL_FRAGMENT_SHADER, "strata/surface_buffer.frag", gpu.shaders->expand("strata/surface_buffer.frag")}});
    buffers_.emplace(settings_.gridCells);
    rasterisationTimer_.emplace();
  }

  void prepare(const FrameState& frame) override {
    const auto start = std::chrono::steady_clock::now();
    if (!nodeHeights_) nodeHeights_ = nodeHeights();  // once the height layer has placed its texels
    const std::vector<SelectedNode> selected =
        selectNodes(frame.view, radius_, heights_.range(), settings_, *nodeHeights_);
    batch_ = batchNodes(selected, frame.view, radius_, settings_.gridCells);
    visibilityMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }

  GeometryStatistics statistics() const override {
    const std::uint64_t nodes = batch_.nodes.size(), cells = std::uint64_t(settings_.gridCells);
    return {int(nodes), nodes * (cells + 1) * (cells + 1),  nodes * 2 * cells * cells, visibilityMs_,
            0.0,        rasterisationTimer_->milliseconds()};
  }

  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_.framebuffer(); }
  HeightRange heights() const override { return heights_.range(); }

 private:
  void useSurface(const View& view);
  NodeHeights nodeHeights() const;

  HeightInput heights_;
  double radius_;
  SelectionSettings settings_;
  std::optional<NodeHeights> nodeHeights_;  // made by the first prepare()
  NodeBatch batch_;
  ShaderProgram surface_;
  std::optional<NodeBuffers> buffers_;
  std::optional<GpuTimer> rasterisationTimer_;
  double visibilityMs_ = 0.0;
  SurfaceBuffer gbuffer_{heights_.shadingNormal()};
};

// The height layer's bounds over each node, where it knows them: a HEALPix pyramid's pages' true ranges, or
// another raster's over the node's cone widened by two vertex spacings (a node is at most the cone's width
// across, gridCells spacings), for the footprints of the heights sampled at its edges.
NodeHeights HealpixGeometry::nodeHeights() const {
  const Layer* layer = heights_.layer();
  if (!layer) return {};
  if (const auto* faces = layer->as<HealpixFaceLayer>(); faces && !faces->faceSamplingFunction().empty())
    return [faces](const NodeKey& key, const NodeCone&) -> std::optional<RegionalHeights> {
      const std::optional<ValueRange> values = faces->faceNodeValues(key.face, key.level, key.ix, key.iy);
      if (!values) return std::nullopt;
      return RegionalHeights{{values->least, values->greatest}, values->finest};
    };
  if (!heights_.boundsRegions()) return {};
  return [this](const NodeKey&, const NodeCone& cone) -> std::optional<RegionalHeights> {
    return heights_.within(cone.widened(4.0 * cone.angle / settings_.gridCells));
  };
}

// The heights' footprint: the threshold asks for `threshold` vertices a pixel, so vertices stand
// 1 / sqrt(threshold) pixels apart, a pixel's angle times that per metre from the eye on the ground.
void HealpixGeometry::useSurface(const View& view) {
  const double pixelAngle = 1.0 / view.pixelsPerRadian();
  surface_.use();
  surface_.set("gridCells", settings_.gridCells);
  surface_.set("planetToEye", glm::mat3(view.planetToEye));
  surface_.set("projection", view.projection);
  surface_.set("planetToReference", glm::mat3(planetToLocal(view.reference)));
  surface_.set("referenceLatitude", glm::vec2(std::sin(view.reference.y), std::cos(view.reference.y)));
  surface_.set("referenceLonlat", glm::vec2(view.reference));
  surface_.set("radius", float(radius_));
  surface_.set("footprintPerMetre", float(pixelAngle / (std::sqrt(settings_.threshold) * radius_)));
  surface_.set("groundLevel", float(groundLevelNear(heights_.range(), glm::length(view.eye) - radius_)));
}

void HealpixGeometry::render(const FrameState& frame) {
  const View& view = frame.view;
  buffers_->upload(batch_);
  gbuffer_.begin(view.width, view.height, samples());
  // No face culling: where relief slopes about as steeply as a grazing view, the triangle through which a ray
  // enters the ground is nearly edge-on, and the rasteriser's rounding may call it back-facing; culled, it
  // left the pixel to the back faces behind it and so to the sky (one pixel 2 m up, 88 degrees, Coverage).
  // The nodes beyond the horizon are culled already, so few back faces reach the rasteriser.
  useSurface(view);
  TextureUnits units;
  if (heights_.layer()) heights_.layer()->bind(surface_, units);
  rasterisationTimer_->begin();
  buffers_->draw();
  rasterisationTimer_->end();
  gbuffer_.end();
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "geometry.healpix";
  type.category = NodeCategory::Geometry;
  type.summary =
      "Twelve HEALPix quadtrees: nodes chosen on the CPU by their size and error on screen, placed on the GPU";
  type.output = PortType::Geometry;
  type.parameters = healpixParameters().declarations();
  HeightInput::declareOn(type);
  type.create = [](const NodeSetup& setup) { return std::make_unique<HealpixGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::healpix

STRATA_PLUGIN("geometry-healpix", "0.1.0", strata::healpix::registerTypes)
