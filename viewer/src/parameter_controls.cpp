#include <strata/viewer/parameter_controls.hpp>

#include <strata/date.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/host/scene_settings.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata::viewer {
namespace {

// Text as a YAML double-quoted scalar, so that colons, brackets and leading spaces stay text.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

// Day numbers as the ISO 8601 dates a pipeline writes.
std::string isoDates(const std::vector<double>& days) {
  std::string text = "[";
  for (std::size_t i = 0; i < days.size(); ++i) text += (i ? ", " : "") + formatIsoDate(days[i]);
  return text + "]";
}

constexpr const char* kCamera = "camera";

// The camera's body has its selector in the scene panel, among the scene's bodies' ids.
constexpr const char* kCameraBody = "body";

// A control for each parameter `set` holds (an optional parameter left unset has no value to show).
void addControls(std::vector<ParameterControl>& controls, const std::string& node, const std::string& type,
                 const std::string& path, const std::vector<ParameterDeclaration>& declarations,
                 const ParameterSet& set) {
  for (const ParameterDeclaration& parameter : declarations)
    if (set.has(parameter.name) && !(path == kCamera && parameter.name == kCameraBody))
      controls.push_back({node, type, path, &parameter, set.value(parameter.name)});
}

// The sections that are maps; the date has its slider in the scene panel.
std::vector<ParameterControl> sceneControls(Engine& engine) {
  const Pipeline& pipeline = engine.pipeline();
  const std::vector<std::pair<const char*, ParameterSet>> sections{
      {"body", bodyParameters().parameters(pipeline.body, {})},
      {kCamera, cameraParameters().parameters(engine.camera(), {})},
      {"cache", cacheParameters().parameters(pipeline.cache, {})},
      {"colour", colourParameters().parameters(pipeline.colour, {})},
  };
  std::vector<ParameterControl> controls;
  for (const auto& [name, set] : sections)
    addControls(controls, name, "scene", name, findSceneSection(name)->parameters, set);
  return controls;
}

}  // namespace

std::vector<ParameterControl> parameterControls(Engine& engine) {
  std::vector<ParameterControl> controls = sceneControls(engine);
  for (const NodeDescription& node : engine.pipeline().nodes) {
    const NodeTypeDeclaration* type = engine.plugins().find(node.type);
    if (!type) continue;
    addControls(controls, node.id, node.type, "nodes." + node.id, type->parameters, node.parameters);
  }
  return controls;
}

std::string overrideOf(const ParameterControl& control, const ParameterValue& value) {
  std::string text = formatValue(value);
  if (std::holds_alternative<std::string>(value)) text = quoted(std::get<std::string>(value));
  if (control.declaration->type == ParameterType::DateList) text = isoDates(std::get<std::vector<double>>(value));
  if (control.declaration->type == ParameterType::Date) text = formatIsoDate(std::get<double>(value));
  return control.path + "." + control.declaration->name + "=" + text;
}

bool apply(Engine& engine, const ParameterControl& control, const ParameterValue& value) {
  if (control.path != kCamera) return engine.set(overrideOf(control, value));
  ParameterSet camera = cameraParameters().parameters(engine.camera(), {});
  camera.set(control.declaration->name, value, {});
  engine.camera() = cameraParameters().read(camera);
  return true;
}

}  // namespace strata::viewer
