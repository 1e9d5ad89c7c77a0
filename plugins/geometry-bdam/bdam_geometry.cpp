// geometry.bdam: the body drawn from P-BDAM's pre-simplified patches [Cignoni et al. 2003], which `strata build-bdam`
// builds from a height raster. Each frame the stateless refinement picks a conforming cut of the twelve bintrees by
// screen-space error on the CPU in double (refinement.hpp), the missing patches are read from the memory-mapped face
// files and decoded (patch_loader.hpp), and the cut is drawn with one multi-draw from the patches held in graphics
// memory (patch_buffers.hpp), into the same deferred texturing buffer as the other generators. docs/bdam.md explains
// the parts.
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <strata/gl/gpu_timer.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/surface_buffer.hpp>
#include <strata/host/page_cache.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>

#include "bdam_data.hpp"
#include "patch_buffers.hpp"
#include "patch_loader.hpp"
#include "plugin_shaders.hpp"
#include "refinement.hpp"

namespace strata::bdam {
namespace {

struct BdamSettings {
  std::filesystem::path path;    // required: the folder `strata build-bdam` wrote
  double pixelError = 3.0;       // the paper's tolerance [Cignoni et al. 2003, §6]
  double cacheMegabytes = 64.0;  // a quarter of the default page cache budget; about 6,000 patches: several views'
  int loadsPerFrame = 64;        // patches read and decoded a frame while the view moves (a frame kept: all)
  bool prefetch = true;          // the paper's speculative prefetch, 0.5 s ahead
};

// Patch slots at the least, whatever cache_mb says: the roots and a coarse view's patches (the paper drew up to 280 a
// frame at 640x480). With fewer than a view needs, the refinement stops where the slots run out.
constexpr std::size_t kFewestSlots = 256;

const ParameterBindings<BdamSettings>& bdamParameters() {
  using S = BdamSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .required(&S::path, {.name = "path",
                               .doc = "the folder of face files `strata build-bdam` wrote (face-0.bdam to "
                                      "face-5.bdam); relative to the pipeline file"})
          .add(&S::pixelError, {.name = "pixel_error",
                                .minimum = 0.1,
                                .maximum = 100.0,
                                .units = "px",
                                .doc = "a patch is drawn once its error seen from the eye is no more than this (3, "
                                       "the paper's tolerance: popping it found virtually eliminated)"})
          .add(&S::cacheMegabytes, {.name = "cache_mb",
                                    .minimum = 1.0,
                                    .maximum = 65536.0,
                                    .units = "MB",
                                    .doc = "graphics memory for patches, least recently drawn out first, out of the "
                                           "pipeline's page cache budget (`cache: {budget}`)"})
          .add(&S::loadsPerFrame, {.name = "loads_per_frame",
                                   .minimum = 1.0,
                                   .maximum = 100000.0,
                                   .doc = "patches read and decoded a frame while the view moves, so that a frame "
                                          "waits for no more; a frame kept (strata render) reads all it needs"})
          .add(&S::prefetch, {.name = "prefetch",
                              .doc = "ask the kernel ahead for the patches the view half a second on will want, "
                                     "the eye moved on as it moved since the last frame (the paper's madvise "
                                     "prefetch)"});
  return bindings;
}

class BdamGeometry : public Node, public SurfaceGeometry {
 public:
  explicit BdamGeometry(const NodeSetup& setup)
      : settings_(bdamParameters().read(setup.parameters)),
        where_(bdamParameters().where(setup.parameters, &BdamSettings::path)),
        cacheWhere_(bdamParameters().where(setup.parameters, &BdamSettings::cacheMegabytes)),
        radius_(setup.body->radius) {}

  void open() override;
  void createResources(GpuContext& gpu) override;
  void prepare(const FrameState& frame) override;
  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_.framebuffer(); }
  HeightRange heights() const override { return heights_; }
  GeometryStatistics statistics() const override {
    return {int(batch_.patches.size()), vertices_, triangles_, visibilityMs_, 0.0, rasterisationTimer_->milliseconds()};
  }

 private:
  std::size_t slots() const;
  std::optional<NodeRecord> record(const BintreeNode& node) const;
  Cut refine(const View& view, const std::function<bool(const BintreeNode&)>& resident) const;
  void prefetchAhead(const FrameState& frame);

  BdamSettings settings_;
  SourceLocation where_, cacheWhere_;
  double radius_;
  HeightRange heights_;
  std::unique_ptr<BdamData> data_;
  std::unique_ptr<PatchLoader> loader_;
  PatchBatch batch_;
  std::vector<PendingPatch> uploads_;
  std::uint64_t vertices_ = 0, triangles_ = 0;
  double visibilityMs_ = 0.0;
  ShaderProgram surface_;
  std::optional<PatchBuffers> buffers_;
  std::optional<GpuTimer> rasterisationTimer_;
  SurfaceBuffer gbuffer_{ShadingNormal::Stored};
};

void BdamGeometry::open() {
  try {
    data_ = std::make_unique<BdamData>(settings_.path);
  } catch (const FaceFileError& error) {
    throw Error(where_, error.what(),
                "build the folder with `strata build-bdam HEIGHTS " + settings_.path.string() + "`");
  }
  if (std::abs(data_->radius() - radius_) > 1e-6 * radius_)
    throw Error(where_,
                "the patches were built on a body of radius " + std::to_string(data_->radius()) +
                    " m, this body's is " + std::to_string(radius_) + " m",
                "build them again with `strata build-bdam ... --radius " + std::to_string(radius_) +
                    "`, or give the pipeline's body that radius");
  heights_ = data_->heights();
  loader_ = std::make_unique<PatchLoader>(*data_, slots());
}

// Slots of the largest patch's size within cache_mb, at least kFewestSlots.
std::size_t BdamGeometry::slots() const {
  const double slotBytes = double(PatchBuffers::slotBytes(data_->mostVertices(), data_->mostIndices()));
  return std::max<std::size_t>(std::size_t(settings_.cacheMegabytes * 1e6 / slotBytes), kFewestSlots);
}

void BdamGeometry::createResources(GpuContext& gpu) {
  surface_ = ShaderProgram(
      {{GL_VERTEX_SHADER, "geometry-bdam/bdam_surface.vert", gpu.shaders->expand("geometry-bdam/bdam_surface.vert")},
       {GL_FRAGMENT_SHADER, "geometry-bdam/bdam_surface.frag",
        gpu.shaders->expand("geometry-bdam/bdam_surface.frag")}});
  gpu.pages->reserve(slots() * PatchBuffers::slotBytes(data_->mostVertices(), data_->mostIndices()), cacheWhere_);
  buffers_.emplace(slots(), data_->mostVertices(), data_->mostIndices());
  rasterisationTimer_.emplace();
}

// A node's error and sphere; none where its record is damaged (the refinement neither splits nor draws it).
std::optional<NodeRecord> BdamGeometry::record(const BintreeNode& node) const {
  try {
    return data_->faceOf(node).node(node);
  } catch (const FaceFileError&) {
    return std::nullopt;
  }
}

Cut BdamGeometry::refine(const View& view, const std::function<bool(const BintreeNode&)>& resident) const {
  return bdam::refine(view, data_->leafLevel(), settings_.pixelError, radius_ + heights_.lowest,
                      {[this](const BintreeNode& node) { return record(node); }, resident});
}

// The refinement on the view half a second on [Cignoni et al. 2003, §4.4: "linear extrapolation of the camera
// position with a 0.5 s look-ahead"], every patch taken as resident, so that it reaches as deep as that view will;
// the kernel is asked for those not resident.
void BdamGeometry::prefetchAhead(const FrameState& frame) {
  if (settings_.prefetch && frame.ahead)
    loader_->prefetch(refine(*frame.ahead, [](const BintreeNode&) { return true; }).drawn);
}

void BdamGeometry::prepare(const FrameState& frame) {
  const auto start = std::chrono::steady_clock::now();
  const bool settle = frame.still || frame.index == 0;
  const auto resident = [this](const BintreeNode& node) { return loader_->resident(node); };
  Cut cut = refine(frame.view, resident);
  for (const BintreeNode& node : cut.drawn) loader_->drawn(node, frame.index);
  while (!cut.missing.empty()) {
    const std::uint64_t before = loader_->loaded();
    loader_->load(cut.missing, std::size_t(settings_.loadsPerFrame), frame.index);
    if (!settle || loader_->loaded() == before) break;
    cut = refine(frame.view, resident);
    for (const BintreeNode& node : cut.drawn) loader_->drawn(node, frame.index);
  }
  prefetchAhead(frame);
  std::vector<PlacedNode> placed;
  vertices_ = triangles_ = 0;
  for (const BintreeNode& node : cut.drawn) {
    const auto [slot, indices] = loader_->drawn(node, frame.index);
    placed.push_back({node, slot, indices});
    vertices_ += loader_->vertices(node);
    triangles_ += indices / 3;
  }
  batch_ = batchPatches(placed, frame.view, radius_, data_->mostVertices(), data_->mostIndices());
  uploads_ = loader_->takePending();
  visibilityMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void BdamGeometry::render(const FrameState& frame) {
  const View& view = frame.view;
  for (const PendingPatch& pending : uploads_) buffers_->upload(pending.slot, pending.patch);
  uploads_.clear();
  gbuffer_.begin(view.width, view.height, samples());
  surface_.use();
  surface_.set("planetToEye", glm::mat3(view.planetToEye));
  surface_.set("projection", view.projection);
  surface_.set("planetToReference", glm::mat3(planetToLocal(view.reference)));
  surface_.set("referenceLatitude", glm::vec2(std::sin(view.reference.y), std::cos(view.reference.y)));
  surface_.set("eyeDistance", float(glm::length(view.eye)));
  rasterisationTimer_->begin();
  buffers_->draw(batch_);
  rasterisationTimer_->end();
  gbuffer_.end();
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();
  type.type = "geometry.bdam";
  type.category = NodeCategory::Geometry;
  type.summary =
      "P-BDAM's pre-simplified patches from `strata build-bdam`, chosen by screen-space error, read from "
      "memory-mapped files";
  type.output = PortType::Geometry;
  type.parameters = bdamParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<BdamGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::bdam

STRATA_PLUGIN("geometry-bdam", "0.1.0", strata::bdam::registerTypes)
