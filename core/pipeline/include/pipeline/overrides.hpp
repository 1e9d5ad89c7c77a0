#pragma once
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "pipeline/source_map.hpp"

namespace strata::loader {

// The keys of a dot-separated PATH ("nodes.relief.scale"), empty ones included for the caller to refuse.
std::vector<std::string> splitKeyPath(const std::string& path);

// Applies --set overrides to the pipeline's YAML tree before it is validated, so an overridden value is
// checked exactly like one written in the file. Each override is "PATH=VALUE":
//  - PATH is dot-separated keys from the top of the file (camera.altitude, nodes.relief.scale). Every
//    key but the last must name an existing map; the last may be new in that map (it is then validated
//    like any key, so a typo gets a did-you-mean).
//  - VALUE is everything after the first '=', read as YAML: 5000, [a, b], {altitude: 5}, "text".
// Overrides apply in order; a later one may write into the value of an earlier one. Each value is
// recorded in `source`, so errors about it point at --set and quote the override. Throws strata::Error
// (file "--set", no line) for an override without '=', with an empty key, with VALUE that is not YAML,
// or whose PATH goes through a missing key or a value that is not a map.
// `root` must be a map (the loader checks that first).
void applyOverrides(YAML::Node& root, const std::vector<std::string>& overrides, SourceMap& source);

}  // namespace strata::loader
