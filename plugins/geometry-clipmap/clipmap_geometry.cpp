// geometry.clipmap: spherical clipmaps [Clasen & Hege 2006]. A static hemisphere of concentric rings about the point
// below the viewer, built and uploaded once (hemisphere_rings.hpp), turned to the viewer and displaced by the height
// layer in the vertex shader each frame, the levels between the horizon and a fill cap a few pixels across drawn
// (drawn_levels.hpp), the sectors out of view left out (sector_culling.hpp): no tree, no cracks by construction,
// triangles of about one size on screen. It draws the same deferred texturing buffer as the other generators.
// docs/clipmap.md explains the parts and what differs from the paper.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

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
#include <strata/plugin/spherical_cap.hpp>

#include "drawn_levels.hpp"
#include "height_clipmaps.hpp"
#include "hemisphere_buffers.hpp"
#include "hemisphere_rings.hpp"
#include "plugin_shaders.hpp"
#include "sector_culling.hpp"

namespace strata::clipmap {
namespace {

const ParameterBindings<RingSettings>& ringParameters() {
  using S = RingSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::steps, {.name = "steps",
                           .minimum = 8.0,
                           .maximum = 4096.0,
                           .doc = "steps around each ring (the paper's n), even: 512 as the paper; a ring's triangles "
                                  "are 2 pi / steps of its radius across, 1.2% at 512"})
          .add(&S::ringsPerLevel, {.name = "rings",
                                   .minimum = 1.0,
                                   .maximum = 256.0,
                                   .doc = "rings a level, each level half as far from the viewer as the one before "
                                          "(the paper's m): 20 as the paper, 20,480 triangles a level at 512 steps"});
  return bindings;
}

RingSettings ringsOf(const NodeSetup& setup) {
  const RingSettings settings = ringParameters().read(setup.parameters);
  if (settings.steps % 2 != 0)
    throw Error(ringParameters().where(setup.parameters, &RingSettings::steps),
                "steps (" + std::to_string(settings.steps) + ") is odd",
                "give an even number: the mesh's halves east and west of the viewer meet along its columns due "
                "north and due south");
  return settings;
}

class ClipmapGeometry : public Node, public SurfaceGeometry {
 public:
  explicit ClipmapGeometry(const NodeSetup& setup)
      : heights_(setup), radius_(setup.body->radius), rings_(buildHemisphereRings(ringsOf(setup))) {}

  void open() override { heights_.open(); }

  void createResources(GpuContext& gpu) override {
    std::map<std::string, std::string> substitutions = heights_.substitutions();
    substitutions["STRATA_PROGRAM_DEFINES"] +=
        "\n#define STRATA_CLIPMAP_LEVELS " + std::to_string(rings_.settings.levels);
    surface_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "geometry-clipmap/clipmap_surface.vert",
          gpu.shaders->expand("geometry-clipmap/clipmap_surface.vert", substitutions)},
         {GL_FRAGMENT_SHADER, "strata/surface_buffer.frag", gpu.shaders->expand("strata/surface_buffer.frag")}});
    if (heights_.layer())
      clipmaps_.emplace(
          clipmapTexels(rings_.settings.steps),
          ShaderProgram({{GL_COMPUTE_SHADER, "geometry-clipmap/clipmap_fill.comp",
                          gpu.shaders->expand("geometry-clipmap/clipmap_fill.comp", substitutions)}}),
          slopedSamplingFunctionOf(*heights_.layer()).empty()
              ? std::optional(ShaderProgram({{GL_COMPUTE_SHADER, "geometry-clipmap/clipmap_slopes.comp",
                                              gpu.shaders->expand("geometry-clipmap/clipmap_slopes.comp")}}))
              : std::nullopt);
    buffers_.emplace(rings_);
    samplingTimer_.emplace();
    rasterisationTimer_.emplace();
  }

  // The levels from the horizon of the whole range of heights to the fill cap, a few pixels at the ground below the
  // eye, as near as the heights there allow; then their sectors in view.
  void prepare(const FrameState& frame) override {
    const auto start = std::chrono::steady_clock::now();
    const HeightsOver heightsOver = [this](const SphericalCap& cap) {
      return heights_.boundsRegions() ? heights_.within(cap).range : heights_.range();
    };
    const double altitude = glm::length(frame.view.eye) - radius_;
    // The ground within the eye's altitude of the point below it: farther ground lies farther than that ground
    // may (an eye below the sphere: the point below it alone).
    const SphericalCap belowEye{directionOf(frame.view.reference),
                                std::clamp(altitude / radius_, 0.0, std::numbers::pi)};
    const double pixel = pixelColatitude(radius_, altitude, heightsOver(belowEye), 1.0 / frame.view.pixelsPerRadian());
    drawn_ = drawnLevels(horizonColatitude(radius_, altitude, heights_.range()), capColatitude(pixel),
                         rings_.settings.levels);
    ranges_ = visibleRanges(rings_, drawn_, frame.view, radius_, heightsOver);
    visibilityMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }

  // Patches: the levels drawn; vertices: those their triangles name, counted three a triangle; subdivision: the
  // height clipmaps' sampling.
  GeometryStatistics statistics() const override {
    std::uint64_t indices = 0;
    for (const IndexRange& range : ranges_) indices += range.count;
    return {drawn_.finest - drawn_.coarsest + 1, indices, indices / 3, visibilityMs_, samplingTimer_->milliseconds(),
            rasterisationTimer_->milliseconds()};
  }

  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_.framebuffer(); }
  HeightRange heights() const override { return heights_.range(); }

 private:
  void useSurface(const View& view);

  HeightInput heights_;
  double radius_;
  HemisphereRings rings_;
  DrawnLevels drawn_;
  std::vector<IndexRange> ranges_;
  ShaderProgram surface_;
  std::optional<HemisphereBuffers> buffers_;
  std::optional<HeightClipmaps> clipmaps_;  // with a height layer
  std::optional<GpuTimer> samplingTimer_, rasterisationTimer_;
  double visibilityMs_ = 0.0;
  SurfaceBuffer gbuffer_{heights_.shadingNormal()};
};

// The frame of the point below the eye, in which the mesh is given, made in double.
void ClipmapGeometry::useSurface(const View& view) {
  const glm::dmat3 localToPlanet = glm::transpose(planetToLocal(view.reference));
  surface_.use();
  surface_.set("localToEye", glm::mat3(view.planetToEye * localToPlanet));
  surface_.set("localToPlanet", glm::mat3(localToPlanet));
  surface_.set("projection", view.projection);
  surface_.set("referenceLatitude", glm::vec2(std::sin(view.reference.y), std::cos(view.reference.y)));
  surface_.set("referenceLonlat", glm::vec2(view.reference));
  surface_.set("radius", float(radius_));
  surface_.set("altitude", float(glm::length(view.eye) - radius_));
}

void ClipmapGeometry::render(const FrameState& frame) {
  const View& view = frame.view;
  samplingTimer_->begin();  // the windows of the levels drawn and of the one outside them they blend into
  if (clipmaps_) clipmaps_->update(view, radius_, *heights_.layer(), std::max(drawn_.coarsest - 1, 0), drawn_.finest);
  samplingTimer_->end();
  gbuffer_.begin(view.width, view.height, samples());
  // No face culling, as geometry.healpix: a triangle through which a grazing ray enters steep relief may round to
  // back-facing. The horizon bounds the levels, so few back faces reach the rasteriser.
  useSurface(view);
  TextureUnits units;
  if (clipmaps_) clipmaps_->bind(surface_, units, view.reference);
  rasterisationTimer_->begin();
  buffers_->draw(ranges_);
  rasterisationTimer_->end();
  gbuffer_.end();
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "geometry.clipmap";
  type.category = NodeCategory::Geometry;
  type.summary = "Spherical clipmaps: a static hemisphere of rings turned to the viewer, displaced on the GPU";
  type.output = PortType::Geometry;
  type.parameters = ringParameters().declarations();
  HeightInput::declareOn(type);
  type.create = [](const NodeSetup& setup) { return std::make_unique<ClipmapGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::clipmap

STRATA_PLUGIN("geometry-clipmap", "0.1.0", strata::clipmap::registerTypes)
