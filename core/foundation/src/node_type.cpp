// The names of the SDK's enumerations, as users read and write them, and lookups in a node type's
// declaration.
#include <strata/plugin/node_type.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace strata {
namespace {

constexpr std::array<std::pair<LayerKind, const char*>, 7> kLayerKindNames{{
    {LayerKind::Height, "height"},
    {LayerKind::Color, "color"},
    {LayerKind::Luminance, "luminance"},
    {LayerKind::Chroma, "chroma"},
    {LayerKind::Normal, "normal"},
    {LayerKind::Mask, "mask"},
    {LayerKind::Scalar, "scalar"},
}};

template <class Declaration>
const Declaration* findByName(const std::vector<Declaration>& declarations, const std::string& name) {
  auto found = std::find_if(declarations.begin(), declarations.end(),
                            [&](const Declaration& declaration) { return declaration.name == name; });
  return found == declarations.end() ? nullptr : &*found;
}

}  // namespace

const char* toString(LayerKind kind) {
  for (const auto& [value, name] : kLayerKindNames)
    if (value == kind) return name;
  return "unknown";
}

bool parseLayerKind(const std::string& text, LayerKind& kind) {
  for (const auto& [value, name] : kLayerKindNames) {
    if (text == name) {
      kind = value;
      return true;
    }
  }
  return false;
}

const char* toString(PortType type) {
  switch (type) {
    case PortType::Layer: return "layer";
    case PortType::Geometry: return "geometry";
  }
  return "unknown";
}

const char* toString(ParameterType type) {
  switch (type) {
    case ParameterType::Boolean: return "boolean";
    case ParameterType::Integer: return "integer";
    case ParameterType::Real: return "real";
    case ParameterType::String: return "string";
    case ParameterType::Path: return "path";
    case ParameterType::Choice: return "choice";
    case ParameterType::RealList: return "real list";
    case ParameterType::DateList: return "date list";
    case ParameterType::Date: return "date";
  }
  return "unknown";
}

const char* toString(NodeCategory category) {
  switch (category) {
    case NodeCategory::Source: return "source";
    case NodeCategory::Compositor: return "compositor";
    case NodeCategory::Geometry: return "geometry";
    case NodeCategory::Output: return "output";
  }
  return "unknown";
}

const PortDeclaration* NodeTypeDeclaration::findInput(const std::string& name) const {
  return findByName(inputs, name);
}

const ParameterDeclaration* NodeTypeDeclaration::findParameter(const std::string& name) const {
  return findByName(parameters, name);
}

}  // namespace strata
