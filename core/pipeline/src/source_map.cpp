#include "pipeline/source_map.hpp"

#include <algorithm>

namespace strata::loader {
namespace {

bool contains(const YAML::Node& tree, const YAML::Node& node) {
  if (tree.is(node)) return true;
  if (tree.IsSequence())
    return std::any_of(tree.begin(), tree.end(), [&](const YAML::Node& item) { return contains(item, node); });
  if (tree.IsMap())
    for (const auto& entry : tree)
      if (contains(entry.first, node) || contains(entry.second, node)) return true;
  return false;
}

}  // namespace

void SourceMap::addOverride(const YAML::Node& value, std::string text) {
  overrides_.emplace_back(value, std::move(text));
}

const std::string* SourceMap::overrideOf(const YAML::Node& node) const {
  // The latest override wins: a later --set may write inside the value of an earlier one.
  for (auto entry = overrides_.rbegin(); entry != overrides_.rend(); ++entry)
    if (contains(entry->first, node)) return &entry->second;
  return nullptr;
}

SourceLocation SourceMap::at(const YAML::Node& node, const std::string& nodeId) const {
  if (overrideOf(node)) return SourceLocation{kOverrideFile, 0, 0, nodeId};
  const YAML::Mark mark = node.Mark();
  if (!lines_ || mark.is_null()) return SourceLocation{file_, 0, 0, nodeId};
  return SourceLocation{file_, mark.line + 1, mark.column + 1, nodeId};  // yaml-cpp counts from 0
}

const YAML::Node& SourceMap::entryAnchor(const YAML::Node& key, const YAML::Node& value) const {
  return !lines_ || key.Mark().is_null() || overrideOf(value) ? value : key;
}

SourceLocation SourceMap::atEntry(const YAML::Node& key, const YAML::Node& value, const std::string& nodeId) const {
  return at(entryAnchor(key, value), nodeId);
}

Error SourceMap::error(const YAML::Node& node, const std::string& nodeId, const std::string& problem,
                       const std::string& fix) const {
  const std::string* setBy = overrideOf(node);
  return Error(at(node, nodeId), setBy ? problem + " (set by --set '" + *setBy + "')" : problem, fix);
}

Error SourceMap::entryError(const YAML::Node& key, const YAML::Node& value, const std::string& nodeId,
                            const std::string& problem, const std::string& fix) const {
  return error(entryAnchor(key, value), nodeId, problem, fix);
}

}  // namespace strata::loader
