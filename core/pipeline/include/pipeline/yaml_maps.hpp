#pragma once
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "pipeline/source_map.hpp"

// Checks shared by every map of a pipeline a user writes: the top level, body, camera, nodes, each node.
namespace strata::loader {

// The key's text; throws at the key when it is not a scalar (`? [a, b]: 1`).
std::string keyText(const YAML::Node& key, const YAML::Node& value, const SourceMap& source,
                    const std::string& nodeId = {});

// Throws when a key appears twice. yaml-cpp keeps both entries, looks up the first and iterates both, so
// a repeated key would silently lose one of its values. `what` names the keys ("key", "node id").
void requireUniqueKeys(const YAML::Node& map, const SourceMap& source, const std::string& what,
                       const std::string& nodeId = {});

// Throws at the first key not in `known`, with a did-you-mean; `what` names the map ("camera").
void requireKnownKeys(const YAML::Node& map, const std::vector<std::string>& known, const SourceMap& source,
                      const std::string& what);

}  // namespace strata::loader
