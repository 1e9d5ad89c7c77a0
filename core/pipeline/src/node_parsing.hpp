#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "pipeline/source_map.hpp"

namespace strata::loader {

// One id a node names on one of its input ports; kept with its YAML scalar for errors found later, once
// every node is known.
struct InputReference {
  std::string port;
  std::string target;
  YAML::Node value;
};

// A node checked on its own: its references to other nodes are checked by connectNodes().
struct ParsedNode {
  NodeDescription description;
  const NodeTypeDeclaration* declaration = nullptr;
  YAML::Node key;    // the id, as written
  YAML::Node value;  // the node's map
  std::vector<InputReference> references;
};

struct NodeContext {
  const SourceMap& source;
  const PluginRegistry& registry;
  std::filesystem::path baseDirectory;  // relative Path parameters resolve against it
};

// Reads one entry of `nodes:` against its type's declaration:
//  - the id must be an identifier: a letter, then letters, digits, '_' or '-';
//  - the value must be a map with a `type` that the registry knows;
//  - every other key is an input port or a parameter of that type; keys appear once;
//  - an input names one node id, or for a list port a sequence of ids (a single id is a list of one);
//  - every input that is not optional is given (an empty list does not count);
//  - every declared parameter ends up in the set: the value given (see parameter_parsing.hpp, located at
//    the value) or the declared default (located at the node); a parameter without default is required.
// Throws strata::Error naming the node.
ParsedNode parseNode(const YAML::Node& key, const YAML::Node& value, const NodeContext& context);

}  // namespace strata::loader
