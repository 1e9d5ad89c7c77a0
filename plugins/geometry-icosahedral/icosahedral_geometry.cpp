// geometry.icosahedral: the view-dependent tessellation of [Kooima 2008, ch. 3]. Visibility on the CPU in
// double (the patch tree), subdivision on the GPU (a compute pass), displacement by the height layer and
// rasterisation into the deferred texturing buffer, with edge windings that leave no cracks between
// patches of different levels. docs/geometry.md explains the parts.
#include <algorithm>
#include <array>
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
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/spherical_cap.hpp>

#include "patch_buffers.hpp"
#include "plugin_shaders.hpp"

namespace strata::icosahedral {
namespace {

// The node's settings as a pipeline writes them, each default's reason beside it.
struct IcosahedralSettings {
  int patches = 300;        // Kooima 2008's np, now a cap: the pixel error asks for fewer wherever it can
  double pixelError = 1.0;  // px: an error under a pixel does not show
  int depth = 5;            // Kooima 2008's default
  int operations = 64;      // keeps the tree's CPU time near half a millisecond and still follows a 30 Hz fly-in
};

const ParameterBindings<IcosahedralSettings>& icosahedralParameters() {
  using S = IcosahedralSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::patches, {.name = "patches",
                             .minimum = 20.0,
                             .maximum = 20000.0,
                             .doc = "the most visible patches the tree may hold, of about equal size on screen (300 is "
                                    "Kooima 2008's np); the pixel error asks for fewer wherever it can"})
          .add(&S::pixelError,
               {.name = "pixel_error",
                .minimum = 0.0,
                .maximum = 100.0,
                .units = "px",
                .doc = "the geometric error a patch may show on screen, from the sphere's chords and the "
                       "terrain's relief within it: the tree refines until no visible patch shows more, "
                       "or it holds `patches` (1: an error under a pixel does not show)",
                .exclusiveMinimum = true})
          .add(&S::depth, {.name = "depth",
                           .minimum = 1.0,
                           .maximum = 8.0,
                           .doc = "subdivisions of each patch: 4^depth triangles (5 is Kooima 2008's default; 1 is the "
                                  "least without T-junctions between levels)"})
          .add(&S::operations, {.name = "operations",
                                .minimum = 0.0,
                                .maximum = 100000.0,
                                .doc = "splits and merges a frame after the first may make (64 keeps the tree's CPU "
                                       "time near half a millisecond and still follows a 30 Hz fly-in); 0 holds the "
                                       "tree the first frame made, to look at it from elsewhere"});
  return bindings;
}

class IcosahedralGeometry : public Node, public SurfaceGeometry {
 public:
  explicit IcosahedralGeometry(const NodeSetup& setup)
      : IcosahedralGeometry(setup, icosahedralParameters().read(setup.parameters)) {}

  void open() override { heights_.open(); }

  void createResources(GpuContext& gpu) override {
    subdivision_ =
        ShaderProgram({{GL_COMPUTE_SHADER, "geometry-icosahedral/subdivide_patches.comp",
                        gpu.shaders->expand("geometry-icosahedral/subdivide_patches.comp", heights_.substitutions())}});
    surface_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "geometry-icosahedral/icosahedral.vert",
          gpu.shaders->expand("geometry-icosahedral/icosahedral.vert")},
         {GL_FRAGMENT_SHADER, "strata/surface_buffer.frag", gpu.shaders->expand("strata/surface_buffer.frag")}});
    buffers_.emplace(table_, windings_);
    subdivisionTimer_.emplace();
    rasterisationTimer_.emplace();
  }

  void prepare(const FrameState& frame) override {
    const auto start = std::chrono::steady_clock::now();
    if (!tree_) plantTree();
    const std::array<ViewVolume, 1> views{ViewVolume(frame.view)};
    if (frame.index == 0 || frame.still)
      tree_->settle(views);  // a still image, or the first of many, is drawn from a settled tree
    else
      tree_->update(views);
    batch_ = batchPatches(tree_->visiblePatches(), frame.view, radius_, tree_->splitDistanceUnit(), table_, windings_);
    batch_.onTerrain = tree_->measuresOnTerrain();
    visibilityMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }

  GeometryStatistics statistics() const override {
    std::uint64_t indices = 0;
    for (const DrawElementsIndirectCommand& draw : batch_.draws) indices += draw.count;
    return {int(batch_.draws.size()),
            batch_.draws.size() * std::uint64_t(table_.vertexCount()),
            indices / 3,
            visibilityMs_,
            subdivisionTimer_->milliseconds(),
            rasterisationTimer_->milliseconds()};
  }

  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_.framebuffer(); }
  HeightRange heights() const override { return heights_.range(); }

 private:
  IcosahedralGeometry(const NodeSetup& setup, const IcosahedralSettings& settings)
      : heights_(setup),
        radius_(setup.body->radius),
        table_(settings.depth),
        windings_(table_),
        treeSettings_{.patches = settings.patches,
                      .operationsPerFrame = settings.operations,
                      .pixelError = settings.pixelError,
                      .depth = settings.depth} {}

  void plantTree();

  HeightInput heights_;
  double radius_;
  SubdivisionTable table_;
  EdgeWindings windings_;
  PatchTreeSettings treeSettings_;
  std::optional<PatchTree> tree_;  // made by the first prepare(), once the height layer has placed its texels
  PatchBatch batch_;
  ShaderProgram subdivision_;
  ShaderProgram surface_;
  std::optional<PatchBuffers> buffers_;
  std::optional<GpuTimer> subdivisionTimer_;
  std::optional<GpuTimer> rasterisationTimer_;
  double visibilityMs_ = 0.0;
  SurfaceBuffer gbuffer_{heights_.shadingNormal()};
};

// The patches' shells take the heights the layer holds, each patch its own where the layer knows them.
void IcosahedralGeometry::plantTree() {
  PatchHeights patchHeights;
  if (heights_.boundsRegions())
    patchHeights = [this](const SphericalTriangle& c) { return heights_.within(sampledCap(c, table_.depth())); };
  tree_.emplace(radius_, heights_.range(), treeSettings_, std::move(patchHeights));
}

void IcosahedralGeometry::render(const FrameState& frame) {
  buffers_->upload(batch_);
  useSubdivision(subdivision_, batch_, table_.depth(), radius_);
  TextureUnits units;
  if (heights_.layer()) heights_.layer()->bind(subdivision_, units);
  subdivisionTimer_->begin();
  buffers_->subdivide();
  subdivisionTimer_->end();

  gbuffer_.begin(frame.view.width, frame.view.height, samples());
  // The far side of the body faces away: half the triangles need no fragments. From below the highest
  // terrain (inside a cut, under a translucent upper layer) the surface may be seen from beneath: no culling.
  if (glm::length(frame.view.eye) > radius_ + heights_.range().highest) glEnable(GL_CULL_FACE);
  surface_.use();
  surface_.set("planetToEye", glm::mat3(frame.view.planetToEye));
  surface_.set("projection", frame.view.projection);
  rasterisationTimer_->begin();
  buffers_->draw();
  rasterisationTimer_->end();
  glDisable(GL_CULL_FACE);
  gbuffer_.end();
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "geometry.icosahedral";
  type.category = NodeCategory::Geometry;
  type.summary = "The icosahedron tessellated for the view: patches chosen on the CPU, subdivided on the GPU";
  type.output = PortType::Geometry;
  type.parameters = icosahedralParameters().declarations();
  HeightInput::declareOn(type);
  type.create = [](const NodeSetup& setup) { return std::make_unique<IcosahedralGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::icosahedral

STRATA_PLUGIN("geometry-icosahedral", "0.1.0", strata::icosahedral::registerTypes)
