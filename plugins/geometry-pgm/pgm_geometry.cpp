// geometry.pgm: spherical projective grid mapping after Mahsman's thesis [Mahsman 2010]. Each frame
// a fixed grid of rays from a sampling camera is cast onto the reference spheres, displaced by the height
// layer and rasterised into the same deferred texturing buffer as geometry.icosahedral, so a pipeline
// switches generators by changing its `type`. docs/pgm.md explains the parts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include <strata/camera.hpp>
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

#include "grid_detail.hpp"
#include "grid_mesh.hpp"
#include "grid_size.hpp"
#include "pgm_cast.hpp"
#include "plugin_shaders.hpp"
#include "reference_spheres.hpp"
#include "sampling_camera.hpp"
#include "visible_radius.hpp"

namespace strata::pgm {
namespace {

// The node's settings as a pipeline writes them, each default's reason beside it.
struct PgmSettings {
  std::string grid = "1024x1024";  // the thesis's largest: a ray for every two pixels at 1920x1080
  double pixelError = 1.0;         // px: an error under a pixel does not show
  double zeta = 0.9;               // the thesis's
};

const ParameterBindings<PgmSettings>& pgmParameters() {
  using S = PgmSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::grid, {.name = "grid",
                          .doc = "the most rays a frame casts, columns x rows, whatever the screen's size (1024x1024, "
                                 "the thesis's largest, is a ray for every two pixels at 1920x1080; a smaller grid "
                                 "undersamples sharp peaks)"})
          .add(&S::pixelError, {.name = "pixel_error",
                                .minimum = 0.0,
                                .maximum = 100.0,
                                .doc = "px: a frame casts the coarsest halving of grid whose geometric error shows no "
                                       "more than this (one pixel is what the eye cannot resolve; 0: grid always)"})
          .add(&S::zeta, {.name = "zeta",
                          .minimum = 0.0,
                          .maximum = 1.0,
                          .doc = "where rays start to turn from the primary sphere to the secondary one behind the "
                                 "horizon, as a share of the angle to the primary's horizon (0.9 is the thesis's)"});
  return bindings;
}

// The grid as `settings` (read from `setup`) write it.
glm::ivec2 gridOf(const PgmSettings& settings, const NodeSetup& setup) {
  const std::string& grid = settings.grid;
  const std::optional<glm::ivec2> size = parseGridSize(grid);
  if (!size)
    throw Error(pgmParameters().where(setup.parameters, &PgmSettings::grid), "grid '" + grid + "' is not a grid size",
                "write columns x rows, each from " + std::to_string(kLeastGridSide) + " to " +
                    std::to_string(kGreatestGridSide) + ", e.g. grid: 1024x1024");
  return *size;
}

// The view as the sampling camera takes it: the symmetric frustum of View::projection on its near plane.
ViewCamera viewCamera(const View& view) {
  const glm::dvec2 halfFrame = view.near * view.halfFrameTangents();
  const double top = halfFrame.y, right = halfFrame.x;
  return {.eye = view.eye,
          .planetToEye = view.planetToEye,
          .left = -right,
          .right = right,
          .bottom = -top,
          .top = top,
          .near = view.near};
}

class PgmGeometry : public Node, public SurfaceGeometry {
 public:
  explicit PgmGeometry(const NodeSetup& setup) : PgmGeometry(setup, pgmParameters().read(setup.parameters)) {}

  // The height layer has opened: where it knows its heights, they must lie within the reference spheres'.
  void open() override { heights_.open(); }

  void createResources(GpuContext& gpu) override {
    castProgram_ = ShaderProgram(
        {{GL_COMPUTE_SHADER, "geometry-pgm/pgm_cast.comp", gpu.shaders->expand("geometry-pgm/pgm_cast.comp")}});
    displacement_ = ShaderProgram({{GL_COMPUTE_SHADER, "geometry-pgm/pgm_displace.comp",
                                    gpu.shaders->expand("geometry-pgm/pgm_displace.comp", heights_.substitutions())}});
    surface_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "geometry-pgm/pgm_grid.vert", gpu.shaders->expand("geometry-pgm/pgm_grid.vert")},
         {GL_FRAGMENT_SHADER, "geometry-pgm/pgm_surface_buffer.frag",
          gpu.shaders->expand("geometry-pgm/pgm_surface_buffer.frag")}});
    castBuffers_.emplace(grid_);
    mesh_.emplace(grid_);
    visibleRadius_.emplace(*gpu.shaders, samples());
    gridTimer_.emplace();
    rasterisationTimer_.emplace();
  }

  GeometryStatistics statistics() const override {
    return {0,
            std::uint64_t(castGrid_.x) * std::uint64_t(castGrid_.y),
            GridMesh::triangles(castGrid_),
            visibilityMs_,
            gridTimer_->milliseconds(),
            rasterisationTimer_->milliseconds()};
  }

  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_.framebuffer(); }
  HeightRange heights() const override { return heights_.range(); }

 private:
  PgmGeometry(const NodeSetup& setup, const PgmSettings& settings)
      : heights_(setup),
        radius_(setup.body->radius),
        grid_(gridOf(settings, setup)),
        castGrid_(grid_),
        pixelError_(settings.pixelError),
        zeta_(settings.zeta) {}

  std::optional<double> leastVisibleHeight(const View& view);
  glm::ivec2 gridFor(const View& view, const SamplingCamera& camera) const;
  void makeGrid(const View& view);
  void rasterise(const View& view);

  HeightInput heights_;
  double radius_;
  glm::ivec2 grid_;      // the most rays a frame casts
  glm::ivec2 castGrid_;  // those the last frame cast (gridForError)
  double pixelError_;
  double zeta_;
  ShaderProgram castProgram_, displacement_, surface_;
  std::optional<CastBuffers> castBuffers_;
  std::optional<GridMesh> mesh_;
  std::optional<VisibleRadius> visibleRadius_;
  std::optional<GpuTimer> gridTimer_;
  std::optional<GpuTimer> rasterisationTimer_;
  using ReducedView = std::pair<std::uint64_t, View>;  // a frame's index and view
  std::deque<ReducedView> reducedViews_;               // the frames whose reductions may be in flight
  double visibilityMs_ = 0.0;
  // The deferred texturing buffer plus color(1): each pixel's height, for visibleRadius_ (infinite where
  // nothing was drawn: visible_radius.hpp).
  SurfaceBuffer gbuffer_{heights_.shadingNormal(), {{GL_R32F, {std::numeric_limits<float>::infinity(), 0, 0, 0}}}};
};

void PgmGeometry::render(const FrameState& frame) {
  makeGrid(frame.view);
  rasterise(frame.view);
  const Framebuffer& buffer = gbuffer_.framebuffer();
  visibleRadius_->reduce(buffer.color(1).id(), buffer.width(), buffer.height(), frame.index);
  reducedViews_.emplace_back(frame.index, frame.view);
  if (reducedViews_.size() > VisibleRadius::kSlots) reducedViews_.pop_front();
}

// The least height seen in an earlier frame whose view stands for this one's; none after a jump.
std::optional<double> PgmGeometry::leastVisibleHeight(const View& view) {
  const std::optional<double> least = visibleRadius_->latest();
  const auto measured = std::ranges::find(reducedViews_, visibleRadius_->latestFrame(), &ReducedView::first);
  if (!least || measured == reducedViews_.end()) return std::nullopt;
  return sameSight(measured->second, view, radius_ + heights_.range().lowest) ? least : std::nullopt;
}

// The reference spheres and the sampling camera on the CPU, in double [Mahsman 2010, §3.4, §3.5], then
// the cast and displacement passes on the GPU [Mahsman 2010, §3.6, §3.7.2].
void PgmGeometry::makeGrid(const View& view) {
  const auto start = std::chrono::steady_clock::now();
  const double distance = glm::length(view.eye);
  const double primary = primaryRadius(leastVisibleHeight(view), radius_, heights_.range().lowest, distance);
  const ReferenceSpheres spheres = referenceSpheres(distance, primary, radius_ + heights_.range().highest);
  const CrossSection section = crossSection(distance, spheres.primary, spheres.secondary, zeta_);
  const SamplingCamera camera = samplingCamera(viewCamera(view), spheres.primary);
  const glm::dmat3 samplingToLocal = planetToLocal(view.reference) * glm::transpose(camera.planetToSampling);
  castGrid_ = gridFor(view, camera);
  visibilityMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  gridTimer_->begin();
  useCast(castProgram_, camera, section, samplingToLocal, castGrid_);
  castBuffers_->cast(castGrid_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  useDisplacement(displacement_, castGrid_, view, radius_, spheres.primary);
  TextureUnits units;
  if (heights_.layer()) heights_.layer()->bind(displacement_, units);
  mesh_->displace(*castBuffers_, castGrid_);
  gridTimer_->end();
}

// The grid's error bounded over the ground the eye can see: the cap out to the horizon of the lowest terrain.
glm::ivec2 PgmGeometry::gridFor(const View& view, const SamplingCamera& camera) const {
  const double distance = glm::length(view.eye), lowest = radius_ + heights_.range().lowest;
  const double horizon = distance > lowest ? std::acos(lowest / distance) : std::numbers::pi;
  const GridScene scene{.radius = radius_,
                        .eyeDistance = distance,
                        .pixelsPerRadian = view.pixelsPerRadian(),
                        .visible = heights_.within(SphericalCap{view.eye / distance, horizon}),
                        .visibleWidth = 2.0 * horizon};
  const glm::dvec2 extent((camera.right - camera.left) / camera.near, (camera.top - camera.bottom) / camera.near);
  return gridForError(grid_, extent, scene, pixelError_);
}

void PgmGeometry::rasterise(const View& view) {
  gbuffer_.begin(view.width, view.height, samples());
  // No face culling: where relief slopes about as steeply as a grazing view, the triangle through which a ray
  // enters the ground is nearly edge-on, and the rasteriser's rounding may call it back-facing; culled, it
  // would leave the pixel to the sky (geometry.healpix lost a pixel so, 2 m up and tilted 88 degrees).
  useGridSurface(surface_, view);
  rasterisationTimer_->begin();
  mesh_->draw(castGrid_);
  rasterisationTimer_->end();
  gbuffer_.end();
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "geometry.pgm";
  type.category = NodeCategory::Geometry;
  type.summary =
      "Projective grid mapping: a grid of rays from the eye cast onto reference spheres, displaced and "
      "rasterised each frame";
  type.output = PortType::Geometry;
  type.parameters = pgmParameters().declarations();
  HeightInput::declareOn(type);
  type.create = [](const NodeSetup& setup) { return std::make_unique<PgmGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::pgm

STRATA_PLUGIN("geometry-pgm", "0.1.0", strata::pgm::registerTypes)
