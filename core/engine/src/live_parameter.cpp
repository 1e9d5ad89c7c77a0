#include "live_parameter.hpp"

#include <yaml-cpp/yaml.h>

#include <strata/plugin/node_type.hpp>

#include "pipeline/overrides.hpp"
#include "pipeline/parameter_parsing.hpp"
#include "pipeline/source_map.hpp"

namespace strata {
namespace {

struct ParameterPath {
  std::string node, name;
};

// "nodes.ID.NAME=..." split, or none for any other path.
std::optional<ParameterPath> parameterPathOf(const std::string& override) {
  const std::string path = override.substr(0, override.find('='));
  const std::size_t first = path.find('.'), second = path.find('.', first + 1);
  if (first == std::string::npos || second == std::string::npos || path.substr(0, first) != "nodes" ||
      path.find('.', second + 1) != std::string::npos)
    return std::nullopt;
  return ParameterPath{path.substr(first + 1, second - first - 1), path.substr(second + 1)};
}

}  // namespace

std::optional<LiveChange> liveChange(const std::string& override, const Pipeline& pipeline,
                                     const PluginRegistry& registry) {
  const std::optional<ParameterPath> path = parameterPathOf(override);
  const NodeDescription* node = path ? pipeline.find(path->node) : nullptr;
  const NodeTypeDeclaration* type = node ? registry.find(node->type) : nullptr;
  const ParameterDeclaration* declared = type ? type->findParameter(path->name) : nullptr;
  if (!declared || !declared->live) return std::nullopt;
  // The override applied to a tree holding just that entry, so its value and its errors are --set's.
  loader::SourceMap source(pipeline.name);
  YAML::Node root;
  root["nodes"][path->node][path->name] = YAML::Node();
  loader::applyOverrides(root, {override}, source);
  const YAML::Node value = root["nodes"][path->node][path->name];
  LiveChange change{path->node, node->parameters};
  const loader::ValueContext context{source, "parameter '" + path->name + "'", path->node};
  change.parameters.set(path->name, loader::parseParameter(value, *declared, context, pipeline.directory),
                        source.at(value, path->node));
  return change;
}

}  // namespace strata
