#pragma once
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/date.hpp>
#include <strata/host/colour_settings.hpp>
#include <strata/host/page_cache_settings.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/sun.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The scene's `date:` (composite.temporal_blend shows the series at it).
struct SceneDate {
  std::optional<DayNumber> date;  // none: not given
};

// One section of a pipeline's scene settings (body, camera, cache, date, sun, colour), declared as node
// parameters are: validated by the same code, listed by `strata plugins --describe scene`, written into
// docs/reference/ and shown by the viewer's scene panel.
struct SceneSection {
  std::string name;  // the pipeline's key
  std::string doc;   // one line
  // Whether the key holds its one parameter's value itself (`date: 2004-06-15`) rather than a map of them.
  bool scalar = false;
  std::vector<ParameterDeclaration> parameters;
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

}  // namespace strata
STRATA_EXPORTS_END
