// The scene's settings, declared once: what `body:`, `camera:`, `cache:`, `colour:`, `date:`, `sun:` and
// `atmosphere:` take, with each default's reason beside it in the settings structs (body.hpp, camera.hpp,
// page_cache_settings.hpp, atmosphere.hpp).
#include <strata/host/scene_settings.hpp>

#include <cstdint>

namespace strata {
namespace {

// The field of view's bounds, deg. A 2 cm checkerboard seen from 1 km through 1024 pixels is crisp down to
// 1e-4 degrees and at 1e-5 blurred and 100 pixels out of place: longitude and latitude reach the GPU relative
// to the point below the eye, in float, which resolves about 1e-6 of the distance. 1e-3 keeps ten times that
// room (at 1e-8 the surface tore, at 1e-320 the projection overflowed and drew nothing) and still frames
// Mars seen from Earth (about 6e-3 degrees across). Up to 179: at 180 the projection is singular.
constexpr double kLeastFieldOfView = 0.001, kMostFieldOfView = 179.0;

// From a boulder to beyond the Sun (6.96e8 m). Far larger, heights and footprints the GPU takes in float
// relative to the radius lose their digits: a body of 1e14 m was drawn speckled, of 1e20 m grey.
constexpr double kLeastRadius = 1.0, kMostRadius = 1.0e9;

constexpr int kMebibyte = 20;  // bits to shift a MiB count into bytes

// The three channels' coefficients, red, green and blue (680, 550 and 440 nm), as a pipeline writes them.
std::vector<double> channelsOf(const glm::dvec3& rgb) { return {rgb.r, rgb.g, rgb.b}; }

SceneSection sectionOf(std::string name, std::string doc, const std::vector<ParameterDeclaration>& parameters,
                       SceneSection::Form form = SceneSection::Form::Map) {
  return {std::move(name), std::move(doc), form, parameters};
}

}  // namespace

const ParameterBindings<Body>& bodyParameters() {
  static const auto bindings =
      ParameterBindings<Body>()
          .add(&Body::name, {.name = "name",
                             .doc = "the body; one of the solar system's (Mars, Moon, Titan: strata/named_bodies.hpp) "
                                    "takes its IAU mean radius"})
          .add(&Body::radius, {.name = "radius",
                               .minimum = kLeastRadius,
                               .maximum = kMostRadius,
                               .units = "m",
                               .doc = "the body's mean radius: a sphere, which heights are measured above; "
                                      "unset: the named body's"});
  return bindings;
}

const ParameterBindings<Camera>& cameraParameters() {
  static const auto bindings =
      ParameterBindings<Camera>()
          .add(&Camera::lon, {.name = "lon",
                              .units = "deg",
                              .doc = "longitude below the eye, east positive; any "
                                     "value, wrapped into [-180, 180)"})
          .add(&Camera::lat, {.name = "lat",
                              .minimum = -90.0,
                              .maximum = 90.0,
                              .units = "deg",
                              .doc = "latitude below the eye, north positive"})
          .add(&Camera::altitude, {.name = "altitude",
                                   .minimum = 0.0,
                                   .units = "m",
                                   .doc = "height of the eye above the body's radius",
                                   .exclusiveMinimum = true})
          .add(&Camera::heading,
               {.name = "heading", .units = "deg", .doc = "direction the view faces, clockwise from north"})
          .add(&Camera::tilt, {.name = "tilt",
                               .minimum = 0.0,
                               .maximum = 90.0,
                               .units = "deg",
                               .doc = "0 looks straight down, 90 at the horizon"})
          .add(&Camera::fov, {.name = "fov",
                              .minimum = kLeastFieldOfView,
                              .maximum = kMostFieldOfView,
                              .units = "deg",
                              .doc = "vertical field of view"})
          .add(&Camera::body, {.name = "body",
                               .doc = "in a scene of several bodies (bodies:), the id of the one the eye is placed "
                                      "over; unset: the first"});
  return bindings;
}

const ParameterBindings<PageCacheSettings>& cacheParameters() {
  static const auto bindings =
      ParameterBindings<PageCacheSettings>()
          .convert<std::int64_t>(
              // 16 MiB hold the upload staging and a few pages of each format.
              {.name = "budget",
               .minimum = 16.0,
               .maximum = double(1 << 20),
               .units = "MiB",
               .doc = "GPU memory for pages, upload staging included, and for what nodes page themselves "
                      "(geometry.bdam's patches)"},
              [](const PageCacheSettings& cache) { return std::int64_t(cache.budgetBytes >> kMebibyte); },
              [](PageCacheSettings& cache, std::int64_t mib) { cache.budgetBytes = std::uint64_t(mib) << kMebibyte; })
          .add(&PageCacheSettings::uploadsPerFrame, {.name = "uploads_per_frame",
                                                     .minimum = 1.0,
                                                     .maximum = 256.0,
                                                     .units = "pages",
                                                     .doc = "pages copied to the GPU per frame"})
          .add(&PageCacheSettings::loaderThreads, {.name = "loader_threads",
                                                   .minimum = 1.0,
                                                   .maximum = 64.0,
                                                   .units = "threads",
                                                   .doc = "threads reading pages"})
          .add(&PageCacheSettings::prefetch,
               {.name = "prefetch",
                .doc = "read the pages the view half a second on will want, into the room the view's own leave"});
  return bindings;
}

const ParameterBindings<ColourSettings>& colourParameters() {
  static const auto bindings = ParameterBindings<ColourSettings>().add(
      &ColourSettings::config,
      {.name = "config",
       .doc = "an OpenColorIO config (.ocio) colours are managed with; unset: $OCIO's, else Strata's own",
       .optional = true});
  return bindings;
}

const ParameterBindings<SceneDate>& dateParameters() {
  static const auto bindings = ParameterBindings<SceneDate>().add(
      &SceneDate::date,
      {.name = "date",
       .type = ParameterType::Date,
       .doc = "the scene's date and time (UTC): what time series show, and where the Earth's sun stands"});
  return bindings;
}

const ParameterBindings<SubsolarPoint>& sunParameters() {
  static const auto bindings =
      ParameterBindings<SubsolarPoint>()
          .add(&SubsolarPoint::lon,
               {.name = "lon", .units = "deg", .doc = "longitude where the sun stands overhead, east positive"})
          .add(&SubsolarPoint::lat, {.name = "lat",
                                     .minimum = -90.0,
                                     .maximum = 90.0,
                                     .units = "deg",
                                     .doc = "latitude where the sun stands overhead"});
  return bindings;
}

const ParameterBindings<Atmosphere>& atmosphereParameters() {
  using A = Atmosphere;
  static const auto bindings =
      ParameterBindings<A>()
          .add(&A::thickness, {.name = "thickness",
                               .minimum = 0.0,
                               .units = "m",
                               .doc = "height above the body's radius where the air ends",
                               .exclusiveMinimum = true})
          .convert<std::vector<double>>(
              {.name = "rayleigh_scattering",
               .minimum = 0.0,
               .units = "1/m",
               .doc = "the molecules' scattering at the ground, [red, green, blue] at 680, 550 and 440 nm",
               .count = 3},
              [](const A& air) { return channelsOf(air.rayleighScattering); },
              [](A& air, std::vector<double> rgb) { air.rayleighScattering = glm::dvec3(rgb[0], rgb[1], rgb[2]); })
          .add(&A::rayleighScaleHeight, {.name = "rayleigh_scale_height",
                                         .minimum = 0.0,
                                         .units = "m",
                                         .doc = "height over which the molecules' density falls by e",
                                         .exclusiveMinimum = true})
          .add(&A::mieScattering, {.name = "mie_scattering",
                                   .minimum = 0.0,
                                   .units = "1/m",
                                   .doc = "the aerosols' scattering at the ground"})
          .add(&A::mieExtinction, {.name = "mie_extinction",
                                   .minimum = 0.0,
                                   .units = "1/m",
                                   .doc = "the aerosols' extinction at the ground: their scattering and absorption"})
          .add(&A::mieScaleHeight, {.name = "mie_scale_height",
                                    .minimum = 0.0,
                                    .units = "m",
                                    .doc = "height over which the aerosols' density falls by e",
                                    .exclusiveMinimum = true})
          .add(&A::mieAsymmetry, {.name = "mie_asymmetry",
                                  .minimum = -0.99,
                                  .maximum = 0.99,
                                  .doc = "the aerosols' mean cosine of scattering (Cornette-Shanks g): near 1, "
                                         "forward, a glare about the sun"})
          .add(&A::groundAlbedo, {.name = "ground_albedo",
                                  .minimum = 0.0,
                                  .maximum = 1.0,
                                  .doc = "the ground's mean reflectance, which lights the air from below"});
  return bindings;
}

const ParameterBindings<SceneBodySettings>& sceneBodyParameters() {
  using S = SceneBodySettings;
  static const auto bindings =
      ParameterBindings<S>()
          .required(&S::pipeline, {.name = "pipeline",
                                   .doc = "the pipeline file that draws the body: its body and nodes; the scene's "
                                          "camera, date and sun stand for its own"})
          .choice(&S::orbit,
                  {.name = "orbit",
                   .doc = "fixed: at position, its axes the first body's; moon: the Moon about the Earth at the "
                          "scene's date, its near side toward the Earth (strata/moon_orbit.hpp)"},
                  {{"fixed", BodyOrbit::Fixed}, {"moon", BodyOrbit::Moon}})
          .add(&S::position, {.name = "position",
                              .units = "m",
                              .doc = "the body's centre [x, y, z] in the first body's planet-fixed axes (orbit: "
                                     "fixed); the first body stands at the origin",
                              .count = 3});
  return bindings;
}

const std::vector<SceneSection>& sceneSections() {
  static const std::vector<SceneSection> sections{
      sectionOf("body", "the planet or moon shown: a sphere", bodyParameters().declarations()),
      sectionOf("camera", "where the first frame is seen from", cameraParameters().declarations()),
      sectionOf("cache", "the GPU page cache (docs/data.md)", cacheParameters().declarations()),
      sectionOf("date", "the scene's date and time (UTC): what time series show, and the Earth's sun",
                dateParameters().declarations(), SceneSection::Form::Value),
      sectionOf("sun", "where the sun stands overhead, fixed; unset: from the date, for the Earth",
                sunParameters().declarations()),
      sectionOf("colour", "how colours are managed (docs/colour.md)", colourParameters().declarations()),
      sectionOf("atmosphere",
                "the body's air, lit by the sun: the sky, and the haze over distant ground (docs/atmosphere.md); "
                "its defaults are the Earth's",
                atmosphereParameters().declarations()),
      sectionOf("bodies",
                "several bodies in one scene, each drawn by its own pipeline, in place of `body` and `nodes` "
                "(docs/pipelines.md)",
                sceneBodyParameters().declarations(), SceneSection::Form::Entries),
  };
  return sections;
}

const char* SceneSection::formNote() const {
  switch (form) {
    case Form::Map: return "";
    case Form::Value: return " (a value, not a map)";
    case Form::Entries: return " (a map from ids to maps)";
  }
  return "";
}

const SceneSection* findSceneSection(const std::string& name) {
  for (const SceneSection& section : sceneSections())
    if (section.name == name) return &section;
  return nullptr;
}

}  // namespace strata
