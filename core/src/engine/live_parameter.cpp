#include "engine/live_parameter.hpp"

#include <algorithm>

#include <strata/node_type.hpp>

namespace strata {

std::optional<std::string> liveParameterNode(const std::string& override, const Pipeline& pipeline,
                                             const PluginRegistry& registry) {
  const std::string path = override.substr(0, override.find('='));
  const std::size_t first = path.find('.'), second = path.find('.', first + 1);
  if (first == std::string::npos || second == std::string::npos || path.substr(0, first) != "nodes" ||
      path.find('.', second + 1) != std::string::npos)
    return std::nullopt;
  const std::string id = path.substr(first + 1, second - first - 1), name = path.substr(second + 1);
  const NodeDescription* node = pipeline.find(id);
  const NodeTypeDeclaration* type = node ? registry.find(node->type) : nullptr;
  if (!type) return std::nullopt;
  const auto& parameters = type->parameters;
  const auto declared = std::find_if(parameters.begin(), parameters.end(),
                                     [&](const ParameterDeclaration& parameter) { return parameter.name == name; });
  return declared != parameters.end() && declared->live ? std::optional<std::string>(id) : std::nullopt;
}

}  // namespace strata
