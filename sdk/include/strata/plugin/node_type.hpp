#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/plugin/parameter.hpp>
#include <strata/plugin/port.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Node;
struct NodeSetup;

enum class NodeCategory { Source, Compositor, Geometry, Output };

const char* toString(NodeCategory category);

using NodeFactory = std::function<std::unique_ptr<Node>(const NodeSetup&)>;

// Everything the core knows about a node type before it makes one: its ports, its parameters and its
// documentation. A plugin registers one of these per type it provides.
struct NodeTypeDeclaration {
  std::string type;  // "source.gdal": category prefix, a dot, a name
  NodeCategory category = NodeCategory::Source;
  std::string summary;  // one line for `strata plugins`
  std::vector<PortDeclaration> inputs;
  std::optional<PortType> output;  // what the node offers downstream; none for outputs
  std::vector<ParameterDeclaration> parameters;
  NodeFactory create;
  // The GLSL files this type's programs and layers include, by the name an `#include "name"` gives:
  // "<plugin>/<file>" by convention (strata_add_plugin(... SHADERS ...) embeds them so and declares
  // strata::plugin::shaderSources() for this field). Every engine's ShaderLibrary holds them.
  std::map<std::string, std::string> shaderSources = {};

  const PortDeclaration* findInput(const std::string& name) const;
  const ParameterDeclaration* findParameter(const std::string& name) const;
};

}  // namespace strata
STRATA_EXPORTS_END
