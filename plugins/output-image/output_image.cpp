// output.image: composes the surface layers per pixel over a geometry's deferred texturing buffer, lights
// the result and delivers 8-bit sRGB frames (PNG files through `strata render`, or a window).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <glm/gtc/constants.hpp>

#include <strata/colour_config.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/texture.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/output.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/sun.hpp>

#include "air_over_surface.hpp"
#include "body_outline.hpp"
#include "outline_fan.hpp"
#include "plugin_shaders.hpp"
#include "translucent_surfaces.hpp"

namespace strata::image {
namespace {

// How the composed colours are lit, in the order composite.frag's `shade` numbers them.
enum class Shading { None, Lambert, Sun };

// The node's settings as a pipeline writes them, each default's reason beside it.
struct ImageSettings {
  Shading shading = Shading::Lambert;
  // 315/45 is the cartographic convention for shaded relief: light from the upper left, so hills do not read
  // as valleys.
  double lightAzimuth = 315.0;
  double lightElevation = 45.0;
  double ambient = 0.25;
  // Civil twilight: until the sun is 6 degrees below the horizon the sky lights the ground enough to see by.
  double twilight = 6.0;
  double opacity = 0.5;  // what lies behind shows as clearly as the translucent surface itself
  // Four samples: the limb's and silhouettes' steps fall to a quarter, and llvmpipe and every GL 4.5 GPU
  // offer them (GL_MAX_SAMPLES is at least 4).
  int samples = 4;
  std::string display;
  std::string view;
};

// The light and the opacity are uniforms, changed the next frame; the display and view are GLSL.
const ParameterBindings<ImageSettings>& imageParameters() {
  using S = ImageSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .choice(&S::shading,
                  {.name = "shading",
                   .doc = "lambert: lit by one light from the view's side (light_azimuth, light_elevation); sun: "
                          "lit by the scene's sun, dark beyond the terminator but for the night layers; none: the "
                          "layers' colours as they are",
                   .live = true},
                  {{"lambert", Shading::Lambert}, {"sun", Shading::Sun}, {"none", Shading::None}})
          .add(&S::lightAzimuth, {.name = "light_azimuth",
                                  .minimum = 0.0,
                                  .maximum = 360.0,
                                  .units = "deg",
                                  .doc = "where the light comes from, clockwise from the top of the image",
                                  .live = true})
          .add(&S::lightElevation, {.name = "light_elevation",
                                    .minimum = 0.0,
                                    .maximum = 90.0,
                                    .units = "deg",
                                    .doc = "the light's angle above the image plane",
                                    .live = true})
          .add(&S::ambient, {.name = "ambient",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .doc = "share of light on surfaces facing away, so the night side keeps its imagery "
                                    "readable; under the sun (shading: sun), by day only",
                             .live = true})
          .add(&S::twilight, {.name = "twilight",
                              .minimum = 0.0,
                              .maximum = 30.0,
                              .units = "deg",
                              .doc = "how far below the horizon the sun's light fades out (shading: sun): the "
                                     "terminator's width",
                              .live = true,
                              .exclusiveMinimum = true})
          .add(&S::opacity, {.name = "opacity",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .doc = "how much of what lies behind each translucent surface it hides",
                             .live = true})
          .choice(&S::samples,
                  {.name = "antialiasing",
                   .doc = "multisample antialiasing, samples per pixel: the body's edge and silhouettes drawn "
                          "without steps; only pixels across them compose more than once"},
                  {{"none", 1}, {"2x", 2}, {"4x", 4}, {"8x", 8}})
          .add(&S::display, {.name = "display",
                             .doc = "the OpenColorIO display the frame is for; empty: the config's default "
                                    "(Strata's: sRGB)"})
          .add(&S::view, {.name = "view",
                          .doc = "the display's view; empty: its default (Strata's sRGB: Standard; Raw shows linear "
                                 "values as they are)"});
  return bindings;
}

const glm::vec3 kBackground(0.0f);  // where there is no body: black, as space

class ImageOutput : public Node, public FrameOutput {
 public:
  explicit ImageOutput(const NodeSetup& setup)
      : geometry_(setup.input("geometry")->geometry()),
        settings_(imageParameters().read(setup.parameters)),
        samplesWhere_(imageParameters().where(setup.parameters, &ImageSettings::samples)),
        displayGlsl_(displayGlsl(setup)),
        translucent_(setup),
        air_(setup) {
    for (Node* node : setup.inputList("surface")) surface_.push_back(node->layer());
    for (Node* node : setup.inputList("night")) night_.push_back(node->layer());
    for (Node* node : setup.inputList("normal")) normal_.push_back(node->layer());
    checkSun(setup);
    geometry_->requestSamples(settings_.samples);
    translucent_.requestSamples(settings_.samples);
  }

  void createResources(GpuContext& gpu) override {
    const int samples = checkedSamples();
    air_.createResources();
    std::string layersGlsl;
    shadedUniforms_.clear();
    for (std::size_t i = 0; i < surface_.size(); ++i) {
      shadedUniforms_.push_back("surfaceShaded" + std::to_string(i));
      layersGlsl += surface_[i]->glslOnce() + "uniform int " + shadedUniforms_.back() + ";\n";
    }
    for (const Layer* layer : night_) layersGlsl += layer->glslOnce();
    for (const Layer* layer : normal_) layersGlsl += layer->glslOnce();
    program_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "output-image/outline.vert", gpu.shaders->expand("output-image/outline.vert")},
         {GL_FRAGMENT_SHADER, "output-image/composite.frag",
          gpu.shaders->expand("output-image/composite.frag",
                              {{"STRATA_DEFERRED_SAMPLER", glslSamplerFor(samples)},
                               {"STRATA_SAMPLES", std::to_string(samples)},
                               {"STRATA_ATMOSPHERE", air_ ? "1" : "0"},
                               {"STRATA_DISPLAY_GLSL", displayGlsl_},
                               {"STRATA_SURFACE_LAYERS_GLSL", layersGlsl},
                               {"STRATA_TRANSLUCENT_GLSL", translucent_.glsl()},
                               {"STRATA_SURFACE_LAYERS_ACCUMULATE", surfaceAccumulation()},
                               {"STRATA_NIGHT_LAYERS_ACCUMULATE", accumulation(night_)},
                               {"STRATA_NORMAL_LAYERS_ACCUMULATE", accumulation(normal_)}})}});
    background_ =
        ShaderProgram({{GL_VERTEX_SHADER, "strata/fullscreen.vert", gpu.shaders->expand("strata/fullscreen.vert")},
                       {GL_FRAGMENT_SHADER, "output-image/background.frag",
                        gpu.shaders->expand("output-image/background.frag", {{"STRATA_DISPLAY_GLSL", displayGlsl_}})}});
    triangle_ = std::make_unique<FullscreenTriangle>();
    fan_ = std::make_unique<OutlineFan>();
  }

  // The layers are composed within the body's outline, and its air's; around it, where neither can show, the
  // frame is the background.
  void render(const FrameState& frame) override {
    if (frame_.width() != frame.view.width || frame_.height() != frame.view.height)
      frame_ = Framebuffer(frame.view.width, frame.view.height, {GL_RGBA8});
    frame_.bind();
    const double highest = std::max({geometry_->heights().highest, translucent_.highest(), air_.thickness(), 0.0});
    const BodyOutline outline = bodyOutline(frame.view, frame.body->radius + highest);
    if (!outline.wholeFrame) paintBackground(frame.transparentBackground);
    program_.use();
    program_.set("lightDirection", lightDirection(frame));
    program_.set("ambient", float(settings_.ambient));
    program_.set("shade", int(settings_.shading));
    program_.set("twilightSine", float(std::sin(glm::radians(settings_.twilight))));
    program_.set("emptyColour", glm::vec3(0.18f));  // mid grey in linear light: clearly "no data", not black
    program_.set("background", kBackground);
    program_.set("transparentBackground", frame.transparentBackground ? 1 : 0);
    program_.set("referenceLonlat", glm::vec2(frame.view.reference));
    program_.set("referenceTrig", sinesAndCosines(frame.view.reference));
    program_.set("frameSize", glm::ivec2(frame.view.width, frame.view.height));
    TextureUnits units;
    units.bind(program_, "surfaceBuffer", geometry_->gbuffer().color(0).id());
    units.bind(program_, "depthBuffer", geometry_->gbuffer().depth().id());
    for (std::size_t i = 0; i < surface_.size(); ++i) {
      surface_[i]->bind(program_, units);
      program_.set(shadedUniforms_[i], surface_[i]->shaded() ? 1 : 0);
    }
    for (const Layer* layer : night_) layer->bind(program_, units);
    for (const Layer* layer : normal_) layer->bind(program_, units);
    translucent_.bind(program_, units, settings_.opacity);
    air_.bind(program_, units, frame);
    fan_->draw(outline.fan);
  }

  void update(const ParameterSet& parameters) override {
    const ImageSettings settings = imageParameters().read(parameters);
    if (settings.shading == Shading::Sun && !sunKnown_)
      throw sunUnknown(imageParameters().where(parameters, &ImageSettings::shading), "shading: sun");
    settings_ = settings;
  }

  FrameOutput* output() override { return this; }
  const Framebuffer& frame() const override { return frame_; }
  const SurfaceGeometry* surface() const override { return geometry_; }
  void write(const std::filesystem::path& file) const override {
    writeImage(file, frame_.width(), frame_.height(), readPixels(frame_));
  }

 private:
  // Around the body's outline: space, or nothing where the frame is laid over other bodies'.
  void paintBackground(bool transparent) {
    if (transparent) {
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      return;
    }
    background_.use();
    background_.set("background", kBackground);
    triangle_->draw();
  }

  // The frame leaves scene-linear light through OpenColorIO's display and view (docs/colour.md): the
  // pipeline's `colour: {config}`, else the config $OCIO names, else Strata's own, whose default is the sRGB
  // display's Standard view.
  static std::string displayGlsl(const NodeSetup& setup) {
    const ColourConfig config =
        ColourConfig::load(setup.colour.config, setup.colour.config.empty() ? setup.where : setup.colour.where);
    const ImageSettings settings = imageParameters().read(setup.parameters);
    const std::string chosen = settings.display.empty() ? config.defaultDisplay() : settings.display;
    const std::string& view = settings.view;
    return config.toDisplay(
        chosen, view.empty() ? config.defaultView(chosen) : view, "strataDisplay",
        imageParameters().where(setup.parameters, view.empty() ? &ImageSettings::display : &ImageSettings::view));
  }

  // The samples per pixel of the geometries' buffers: what this node asked for, or more where another reader
  // asked for more. Throws strata::Error at `antialiasing` where the GL offers fewer, or where the translucent
  // geometries were asked for other samples than the opaque one.
  int checkedSamples() const {
    const int samples = geometry_->samples();
    GLint colour = 1, depth = 1;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colour);
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depth);
    const int offered = std::min(colour, depth);
    if (samples > offered)
      throw Error(
          samplesWhere_,
          "this GL draws at most " + std::to_string(offered) + " samples per pixel, not " + std::to_string(samples),
          "set antialiasing to " + std::to_string(offered) + "x or fewer");
    if (!translucent_.sampledAs(samples))
      throw Error(samplesWhere_, "the translucent geometries draw other samples per pixel than the opaque one",
                  "give every output that reads these geometries the same antialiasing");
    return samples;
  }

  // [Kooima 2008, §4.1.2]: each layer's value x weight into rgb, the weight into alpha, for composite.frag.
  static std::string accumulation(const std::vector<const Layer*>& layers) {
    std::string accumulate;
    for (const Layer* layer : layers) accumulate += "{ " + weighted(*layer) + " accumulated += c; }\n";
    return accumulate;
  }

  // The same for the surface layers, into `shaded` for those whose colours hold light already (Layer::shaded,
  // uniform surfaceShaded<i>, as each frame finds it), which are not lit again.
  std::string surfaceAccumulation() const {
    std::string accumulate;
    for (std::size_t i = 0; i < surface_.size(); ++i)
      accumulate += "{ " + weighted(*surface_[i]) + " if (" + shadedUniforms_[i] +
                    " == 1) shaded += c; else accumulated += c; }\n";
    return accumulate;
  }

  // `c`, the layer's value x weight and its weight, at the sample's point `p`.
  static std::string weighted(const Layer& layer) {
    return "vec4 v = " + layer.samplingFunction() + "(p); vec4 c = vec4(v." +
           (layer.kind() == LayerKind::Luminance ? "rrr" : "rgb") + " * v.a, v.a);";
  }

  // Throws strata::Error at `shading` where it asks for the sun and the scene places none, and at the node
  // where night layers are given without the sun that would show them.
  void checkSun(const NodeSetup& setup) {
    sunKnown_ = setup.sun.has_value();
    const SourceLocation shadingWhere = imageParameters().where(setup.parameters, &ImageSettings::shading);
    if (settings_.shading == Shading::Sun && !sunKnown_) throw sunUnknown(shadingWhere, "shading: sun");
    if (!night_.empty() && settings_.shading != Shading::Sun)
      throw Error(shadingWhere, "night layers are given, but only the sun's shading has a night to show them in",
                  "set shading: sun, or leave out the night input");
  }

  // Toward the light, planet-fixed: the scene's sun (shading: sun), or the light given in the view.
  glm::vec3 lightDirection(const FrameState& frame) const {
    if (settings_.shading == Shading::Sun && frame.sun) return glm::vec3(sunDirection(*frame.sun));
    return lightInView(frame.view);
  }

  // The light, given in the view (azimuth clockwise from the top of the image, elevation above the image
  // plane toward the viewer), turned into planet-fixed axes.
  glm::vec3 lightInView(const View& view) const {
    const double azimuth = glm::radians(settings_.lightAzimuth);
    const double elevation = glm::radians(settings_.lightElevation);
    const glm::dvec3 inView(std::sin(azimuth) * std::cos(elevation), std::cos(azimuth) * std::cos(elevation),
                            std::sin(elevation));
    return glm::vec3(glm::transpose(view.planetToEye) * inView);
  }

  SurfaceGeometry* geometry_;
  ImageSettings settings_;
  SourceLocation samplesWhere_;  // the node's `antialiasing`, for errors about it
  std::string displayGlsl_;
  std::vector<const Layer*> surface_;
  std::vector<std::string> shadedUniforms_;  // each surface layer's uniform saying whether it is shaded already
  std::vector<const Layer*> night_;
  std::vector<const Layer*> normal_;
  bool sunKnown_ = false;  // whether the scene places the sun (NodeSetup::sun): shading: sun needs it
  TranslucentSurfaces translucent_;
  AirOverSurface air_;
  ShaderProgram program_;
  ShaderProgram background_;
  std::unique_ptr<FullscreenTriangle> triangle_;  // made with the GL resources, not at construction
  std::unique_ptr<OutlineFan> fan_;
  Framebuffer frame_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "output.image";
  type.category = NodeCategory::Output;
  type.summary = "Composes surface layers over a geometry, lights them and delivers 8-bit sRGB frames (PNG)";
  type.inputs = {
      {.name = "geometry", .type = PortType::Geometry, .doc = "the surface to colour (a geometry generator)"},
      {.name = "surface",
       .type = PortType::Layer,
       .kinds = {LayerKind::Color, LayerKind::Luminance},
       .list = true,
       .optional = true,
       .doc = "layers draped on it, blended by coverage where they overlap; none: grey"},
      {.name = "night",
       .type = PortType::Layer,
       .kinds = {LayerKind::Color, LayerKind::Luminance},
       .list = true,
       .optional = true,
       .doc = "layers shown unlit where the sun has set (shading: sun), fading in through the twilight: city "
              "lights"},
      {.name = "normal",
       .type = PortType::Layer,
       .kinds = {LayerKind::Normal},
       .list = true,
       .optional = true,
       .doc = "normal maps turning the surface's shading normal, blended by coverage where they overlap: relief "
              "finer than the geometry's heights"},
      {.name = "translucent",
       .type = PortType::Geometry,
       .list = true,
       .optional = true,
       .doc = "surfaces laid translucent over it where they lie nearer, farthest first (a stack's upper layers)"},
      {.name = "translucent_surface",
       .type = PortType::Layer,
       .kinds = {LayerKind::Color},
       .list = true,
       .optional = true,
       .doc = "one colour layer per translucent geometry, in the same order"},
  };
  type.parameters = imageParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<ImageOutput>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::image

STRATA_PLUGIN("output-image", "0.1.0", strata::image::registerTypes)
