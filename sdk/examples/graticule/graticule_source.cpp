// source.graticule: meridians and parallels as a colour layer, drawn on the CPU into a global
// equirectangular raster. An example of a plugin built out of tree against an installed Strata SDK: it
// uses only the public headers under <strata/...> and links only Strata::core.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <strata/error.hpp>
#include <strata/plugin.hpp>
#include <strata/plugin_registry.hpp>
#include <strata/raster_layer.hpp>

namespace graticule {
namespace {

// What to draw, read once from the node's validated parameters.
struct GraticuleStyle {
  double spacing = 0.0;           // degrees between neighbouring lines
  int width = 0;                  // texels across a line
  std::array<float, 3> colour{};  // linear RGB
  int texelsPerDegree = 0;
};

GraticuleStyle styleOf(const strata::ParameterSet& parameters) {
  // The declaration's bounds are inclusive, so it cannot say "more than 0"; zero is refused here, at the
  // value's line in the pipeline file, because it would ask for infinitely many lines.
  if (parameters.real("spacing") <= 0.0)
    throw strata::Error(parameters.where("spacing"), "spacing must be more than 0 degrees",
                        "give the degrees between lines, e.g. `spacing: 15`");
  GraticuleStyle style;
  style.spacing = parameters.real("spacing");
  style.width = static_cast<int>(parameters.integer("width"));
  style.texelsPerDegree = static_cast<int>(parameters.integer("resolution"));
  const std::vector<double>& colour = parameters.reals("color");  // exactly 3: the declaration's count
  for (std::size_t c = 0; c < 3; ++c) style.colour[c] = static_cast<float>(colour[c]);
  return style;
}

// The texel boundaries (columns from the antimeridian) where meridians lie: every whole multiple of the
// spacing. The loop stops short of +180, the meridian at -180 again, which lineMask draws across the seam.
std::vector<long> meridianColumns(const GraticuleStyle& style) {
  std::vector<long> columns;
  for (double k = std::ceil(-180.0 / style.spacing); k * style.spacing < 180.0; ++k)
    columns.push_back(std::lround((k * style.spacing + 180.0) * style.texelsPerDegree));
  return columns;
}

// The texel boundaries (rows from the north pole) where parallels lie, strictly between the poles: a pole
// is a point, where the meridians meet already.
std::vector<long> parallelRows(const GraticuleStyle& style) {
  std::vector<long> rows;
  for (double k = std::floor(-90.0 / style.spacing) + 1.0; k * style.spacing < 90.0; ++k)
    rows.push_back(std::lround((90.0 - k * style.spacing) * style.texelsPerDegree));
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
strata::RasterImage drawGraticule(const GraticuleStyle& style) {
  strata::RasterImage image;
  image.width = 360 * style.texelsPerDegree;
  image.height = 180 * style.texelsPerDegree;
  image.channels = 4;
  const std::vector<bool> onMeridian = lineMask(image.width, meridianColumns(style), style.width, true);
  const std::vector<bool> onParallel = lineMask(image.height, parallelRows(style), style.width, false);
  const auto width = static_cast<std::size_t>(image.width), height = static_cast<std::size_t>(image.height);
  image.texels.assign(width * height * 4, 0.0f);
  for (std::size_t row = 0; row < height; ++row)
    for (std::size_t column = 0; column < width; ++column) {
      if (!onParallel[row] && !onMeridian[column]) continue;
      float* texel = &image.texels[(row * width + column) * 4];
      for (std::size_t c = 0; c < 3; ++c) texel[c] = style.colour[c];  // times coverage 1
      texel[3] = 1.0f;
    }
  return image;
}

// The node: draws its raster in open() (a worker thread, no OpenGL), uploads it in createResources() (the
// GL thread), then offers the layer downstream. Sampling, filtering and blending are RasterLayer's.
class GraticuleSource : public strata::Node {
 public:
  explicit GraticuleSource(const strata::NodeSetup& setup)
      : style_(styleOf(setup.parameters)), plugins_(*setup.plugins), layer_(setup.id, strata::LayerKind::Color) {}

  void open() override { image_ = drawGraticule(style_); }

  void createResources(strata::GpuContext&) override {
    layer_.upload(image_, strata::geographicGeoreference(plugins_, {}, image_.width, image_.height));  // the globe
    image_ = {};  // the texture holds it now
  }

  // Sampled from each point's offset to the point below the eye, so that its lines stay exact up close
  // anywhere on the body.
  void prepare(const strata::FrameState& frame) override { layer_.setReference(frame.view.reference); }

  strata::Layer* layer() override { return &layer_; }

 private:
  GraticuleStyle style_;
  const strata::PluginRegistry& plugins_;
  strata::RasterLayer layer_;
  strata::RasterImage image_;
};

// The one declaration from which the core derives validation, error messages and `strata plugins --describe`.
strata::NodeTypeDeclaration declaration() {
  using strata::ParameterType;
  strata::NodeTypeDeclaration type;
  type.type = "source.graticule";
  type.category = strata::NodeCategory::Source;
  type.summary = "Meridians and parallels every `spacing` degrees, a colour layer to drape over imagery";
  type.output = strata::PortType::Layer;
  type.parameters = {
      // 30: the customary interval of whole-globe maps; from orbit it frames continents without hiding them.
      {.name = "spacing",
       .type = ParameterType::Real,
       .defaultValue = 30.0,
       .minimum = 0.0,
       .maximum = 90.0,
       .units = "deg",
       .doc = "degrees between neighbouring meridians and between parallels; more than 0"},
      // 2: even widths centre a line on its meridian (which falls between two texels); at 8 texels per
      // degree that is a quarter of a degree, about 28 km on Earth.
      {.name = "width",
       .type = ParameterType::Integer,
       .defaultValue = std::int64_t(2),
       .minimum = 1.0,
       .maximum = 16.0,
       .units = "texel",
       .doc = "line width in texels of the layer's raster"},
      // A warm yellow: it stands apart from blue ocean, green and brown land and white cloud alike.
      {.name = "color",
       .type = ParameterType::RealList,
       .defaultValue = std::vector<double>{1.0, 0.85, 0.2},
       .minimum = 0.0,
       .maximum = 1.0,
       .doc = "line colour as linear RGB, each from 0 to 1",
       .count = 3},
      // 8: a 2880x1440 raster (32 MiB of half floats on the GPU, before mipmaps) with more texels per
      // degree than a whole-globe view like demo.yaml's has pixels even at 1920x1080 (under 4), so lines
      // stay sharp. At most 22: 360 x 22 = 7920 texels, within the 8192 that a RasterLayer's single
      // texture may safely span on every OpenGL 4.5 GPU.
      {.name = "resolution",
       .type = ParameterType::Integer,
       .defaultValue = std::int64_t(8),
       .minimum = 1.0,
       .maximum = 22.0,
       .units = "texel/deg",
       .doc = "texels per degree of the raster the lines are drawn into"},
  };
  type.create = [](const strata::NodeSetup& setup) { return std::make_unique<GraticuleSource>(setup); };
  return type;
}

void registerTypes(strata::PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace graticule

STRATA_PLUGIN("graticule", "0.1.0", graticule::registerTypes)
