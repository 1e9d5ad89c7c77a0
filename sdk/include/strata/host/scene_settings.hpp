#pragma once
#include <filesystem>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/atmosphere.hpp>
#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/date.hpp>
#include <strata/host/colour_settings.hpp>
#include <strata/host/page_cache_settings.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/sun.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The scene's `date:` (composite.temporal_blend shows the series at it).
struct SceneDate {
  std::optional<DayNumber> date;  // none: not given
};

// One section of a pipeline's scene settings (body, camera, cache, date, sun, colour, bodies), declared as node
// parameters are: validated by the same code, listed by `strata plugins --describe scene`, written into
// docs/reference/ and shown by the viewer's scene panel.
struct SceneSection {
  std::string name;  // the pipeline's key
  std::string doc;   // one line
  enum class Form {
    Map,      // a map of the parameters: `camera: {lon: 10, altitude: 2e7}`
    Value,    // its one parameter's value itself: `date: 2004-06-15`
    Entries,  // a map from ids the pipeline chooses to maps of the parameters: `bodies: {moon: {pipeline: ...}}`
  };
  Form form = Form::Map;
  std::vector<ParameterDeclaration> parameters;

  // How the form is written, for listings: "", " (a value, not a map)", " (a map from ids to maps)".
  const char* formNote() const;
};

// One entry of a scene of several bodies (`bodies:`): the pipeline that draws the body, and where it stands.
struct SceneBodySettings {
  std::filesystem::path pipeline;
  BodyOrbit orbit = BodyOrbit::Fixed;
  std::vector<double> position{0.0, 0.0, 0.0};  // m: the first body sits at the scene's origin
};

// The sections in the order a pipeline usually writes them.
const std::vector<SceneSection>& sceneSections();
const SceneSection* findSceneSection(const std::string& name);

// The bindings from each section's parameters to the settings they give.
const ParameterBindings<Body>& bodyParameters();
const ParameterBindings<Camera>& cameraParameters();
const ParameterBindings<PageCacheSettings>& cacheParameters();
const ParameterBindings<ColourSettings>& colourParameters();
const ParameterBindings<SceneDate>& dateParameters();
const ParameterBindings<SubsolarPoint>& sunParameters();
const ParameterBindings<Atmosphere>& atmosphereParameters();
const ParameterBindings<SceneBodySettings>& sceneBodyParameters();

}  // namespace strata
STRATA_EXPORTS_END
