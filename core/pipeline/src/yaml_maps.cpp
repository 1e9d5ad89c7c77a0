#include "pipeline/yaml_maps.hpp"

#include <algorithm>
#include <map>

#include "pipeline/suggestions.hpp"
#include "pipeline/value_reading.hpp"

namespace strata::loader {

std::string keyText(const YAML::Node& key, const YAML::Node& value, const SourceMap& source,
                    const std::string& nodeId) {
  if (key.IsScalar()) return key.Scalar();
  throw source.entryError(key, value, nodeId, "a key must be a name, got " + describe(key),
                          "write a plain name before the ':'");
}

void requireUniqueKeys(const YAML::Node& map, const SourceMap& source, const std::string& what,
                       const std::string& nodeId) {
  std::map<std::string, SourceLocation> seen;
  for (const auto& entry : map) {
    const std::string key = keyText(entry.first, entry.second, source, nodeId);
    auto [first, added] = seen.emplace(key, source.atEntry(entry.first, entry.second));
    if (!added)
      throw source.entryError(entry.first, entry.second, nodeId,
                              what + " '" + key + "' appears twice; it is first at " + first->second.str(),
                              "remove or rename one of them");
  }
}

void requireKnownKeys(const YAML::Node& map, const std::vector<std::string>& known, const SourceMap& source,
                      const std::string& what) {
  for (const auto& entry : map) {
    const std::string key = keyText(entry.first, entry.second, source);
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw source.entryError(entry.first, entry.second, {},
                              "unknown key '" + key + "' in " + what + didYouMean(key, known),
                              "the keys of " + what + " are " + quotedList(known));
  }
}

}  // namespace strata::loader
