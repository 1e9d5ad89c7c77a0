#include <strata/viewer/parameter_controls.hpp>

#include <strata/date.hpp>
#include <strata/node_type.hpp>
#include <strata/pipeline.hpp>
#include <strata/plugin_registry.hpp>

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

}  // namespace

std::vector<ParameterControl> parameterControls(Engine& engine) {
  std::vector<ParameterControl> controls;
  for (const NodeDescription& node : engine.pipeline().nodes) {
    const NodeTypeDeclaration* type = engine.plugins().find(node.type);
    if (!type) continue;
    for (const ParameterDeclaration& parameter : type->parameters)
      if (node.parameters.has(parameter.name))  // an optional parameter left unset has no value to show
        controls.push_back({node.id, node.type, &parameter, node.parameters.value(parameter.name)});
  }
  return controls;
}

std::string overrideOf(const ParameterControl& control, const ParameterValue& value) {
  std::string text = formatValue(value);
  if (std::holds_alternative<std::string>(value)) text = quoted(std::get<std::string>(value));
  if (control.declaration->type == ParameterType::DateList) text = isoDates(std::get<std::vector<double>>(value));
  return "nodes." + control.node + "." + control.declaration->name + "=" + text;
}

bool apply(Engine& engine, const ParameterControl& control, const ParameterValue& value) {
  return engine.set(overrideOf(control, value));
}

}  // namespace strata::viewer
