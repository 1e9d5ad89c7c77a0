// source.graticule: meridians and parallels as a colour layer, drawn on the CPU into a global
// equirectangular raster. An example of a plugin built out of tree against an installed Strata SDK: it
// uses only the public headers under <strata/...> and links only Strata::core.
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include <strata/error.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/plugin_registry.hpp>
#include <strata/plugin/raster_layer.hpp>

namespace graticule {
namespace {

// The node's settings as a pipeline writes them, each default's reason beside it.
struct GraticuleSettings {
  // 30: the customary interval of whole-globe maps; from orbit it frames continents without hiding them.
  double spacing = 30.0;
  // 2: even widths centre a line on its meridian (which falls between two texels); at 8 texels per degree
  // that is a quarter of a degree, about 28 km on Earth.
  int width = 2;
  // A warm yellow: it stands apart from blue ocean, green and brown land and white cloud alike.
  std::vector<double> colour{1.0, 0.85, 0.2};
  // 8: a 2880x1440 raster (32 MiB of half floats on the GPU, before mipmaps) with more texels per degree
  // than a whole-globe view like demo.yaml's has pixels even at 1920x1080 (under 4), so lines stay sharp.
  // At most 22: 360 x 22 = 7920 texels, within the 8192 that a RasterLayer's single texture may safely
  // span on every OpenGL 4.5 GPU.
  int texelsPerDegree = 8;
};

// The one declaration of each parameter, from which the core derives validation, error messages,
// `strata plugins --describe` and docs/reference/; the node reads them back typed, never by name.
const strata::ParameterBindings<GraticuleSettings>& graticuleParameters() {
  using S = GraticuleSettings;
  static const auto bindings =
      strata::ParameterBindings<S>()
          .add(&S::spacing, {.name = "spacing",
                             .minimum = 0.0,
                             .maximum = 90.0,
                             .units = "deg",
                             .doc = "degrees between neighbouring meridians and between parallels; more than 0"})
          .add(&S::width, {.name = "width",
                           .minimum = 1.0,
                           .maximum = 16.0,
                           .units = "texel",
                           .doc = "line width in texels of the layer's raster"})
          .add(&S::colour, {.name = "color",
                            .minimum = 0.0,
                            .maximum = 1.0,
                            .doc = "line colour as linear RGB, each from 0 to 1",
                            .count = 3})
          .add(&S::texelsPerDegree, {.name = "resolution",
                                     .minimum = 1.0,
                                     .maximum = 22.0,
                                     .units = "texel/deg",
                                     .doc = "texels per degree of the raster the lines are drawn into"});
  return bindings;
}

// What to draw, read once from the node's validated parameters. The declared range admits 0 (its minimum
// is inclusive); zero is refused here, at the value's line in the pipeline file, because it would ask for
// infinitely many lines.
GraticuleSettings settingsOf(const strata::ParameterSet& parameters) {
  const GraticuleSettings settings = graticuleParameters().read(parameters);
  if (settings.spacing <= 0.0)
    throw strata::Error(graticuleParameters().where(parameters, &GraticuleSettings::spacing),
                        "spacing must be more than 0 degrees", "give the degrees between lines, e.g. `spacing: 15`");
  return settings;
}

// The texel boundaries (columns from the antimeridian) where meridians lie: every whole multiple of the
// spacing. The loop stops short of +180, the meridian at -180 again, which lineMask draws across the seam.
std::vector<long> meridianColumns(const GraticuleSettings& settings) {
  std::vector<long> columns;
  for (double k = std::ceil(-180.0 / settings.spacing); k * settings.spacing < 180.0; ++k)
    columns.push_back(std::lround((k * settings.spacing + 180.0) * settings.texelsPerDegree));
  return columns;
}

// The texel boundaries (rows from the north pole) where parallels lie, strictly between the poles: a pole
// is a point, where the meridians meet already.
std::vector<long> parallelRows(const GraticuleSettings& settings) {
  std::vector<long> rows;
  for (double k = std::floor(-90.0 / settings.spacing) + 1.0; k * settings.spacing < 90.0; ++k)
    rows.push_back(std::lround((90.0 - k * settings.spacing) * settings.texelsPerDegree));
  return rows;
}

// Which of `size` texels a line covers, for lines `width` texels wide centred on `boundaries`. Lines lie on
// the boundary between two texels, so an even width centres them exactly. Columns wrap round the globe;
// rows stop at the poles.
std::vector<bool> lineMask(long size, const std::vector<long>& boundaries, int width, bool wraps) {
  std::vector<bool> covered(static_cast<std::size_t>(size), false);
  for (long boundary : boundaries)
    for (long texel = boundary - width / 2; texel < boundary - width / 2 + width; ++texel) {
      const long index = wraps ? (texel % size + size) % size : texel;
      if (index >= 0 && index < size) covered[static_cast<std::size_t>(index)] = true;
    }
  return covered;
}

// The whole globe at `texelsPerDegree`: the line colour with coverage 1 on lines, coverage 0 (transparent,
// so the layers below show through) elsewhere. Texels are premultiplied RGBA, row 0 at the north edge.
strata::RasterImage drawGraticule(const GraticuleSettings& settings) {
  strata::RasterImage image;
  image.width = 360 * settings.texelsPerDegree;
  image.height = 180 * settings.texelsPerDegree;
  image.channels = 4;
  const std::vector<bool> onMeridian = lineMask(image.width, meridianColumns(settings), settings.width, true);
  const std::vector<bool> onParallel = lineMask(image.height, parallelRows(settings), settings.width, false);
  const auto width = static_cast<std::size_t>(image.width), height = static_cast<std::size_t>(image.height);
  image.texels.assign(width * height * 4, 0.0f);
  for (std::size_t row = 0; row < height; ++row)
    for (std::size_t column = 0; column < width; ++column) {
      if (!onParallel[row] && !onMeridian[column]) continue;
      float* texel = &image.texels[(row * width + column) * 4];
      for (std::size_t c = 0; c < 3; ++c) texel[c] = static_cast<float>(settings.colour[c]);  // times coverage 1
      texel[3] = 1.0f;
    }
  return image;
}

// The node: draws its raster in open() (a worker thread, no OpenGL), uploads it in createResources() (the
// GL thread), then offers the layer downstream. Sampling, filtering and blending are RasterLayer's.
class GraticuleSource : public strata::Node {
 public:
  explicit GraticuleSource(const strata::NodeSetup& setup)
      : settings_(settingsOf(setup.parameters)), plugins_(*setup.plugins), layer_(setup.id, strata::LayerKind::Color) {}

  void open() override { image_ = drawGraticule(settings_); }

  void createResources(strata::GpuContext&) override {
    layer_.upload(image_, strata::geographicGeoreference(plugins_, {}, image_.width, image_.height));  // the globe
    image_ = {};  // the texture holds it now
  }

  // Sampled from each point's offset to the point below the eye, so that its lines stay exact up close
  // anywhere on the body.
  void prepare(const strata::FrameState& frame) override { layer_.setReference(frame.view.reference); }

  strata::Layer* layer() override { return &layer_; }

 private:
  GraticuleSettings settings_;
  const strata::PluginRegistry& plugins_;
  strata::RasterLayer layer_;
  strata::RasterImage image_;
};

// The node type: its name, what it offers, its parameters (declared above) and how to make it.
strata::NodeTypeDeclaration declaration() {
  strata::NodeTypeDeclaration type;
  type.type = "source.graticule";
  type.category = strata::NodeCategory::Source;
  type.summary = "Meridians and parallels every `spacing` degrees, a colour layer to drape over imagery";
  type.output = strata::PortType::Layer;
  type.parameters = graticuleParameters().declarations();
  type.create = [](const strata::NodeSetup& setup) { return std::make_unique<GraticuleSource>(setup); };
  return type;
}

void registerTypes(strata::PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace graticule

STRATA_PLUGIN("graticule", "0.1.0", graticule::registerTypes)
