#pragma once
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <strata/error.hpp>

namespace strata::loader {

// Says where a YAML node of the pipeline came from: a line and column of the file, or a --set override.
// Overrides are parsed from their own text, so their marks mean nothing in the file; they are recognised
// by identity instead (yaml-cpp's Node::is), which also covers the nodes inside an overriding value.
class SourceMap {
 public:
  // `lines`: whether the document's nodes carry lines and columns; one built in code
  // (PipelineBuilder) has none, and its messages name the node alone.
  explicit SourceMap(std::string file, bool lines = true) : file_(std::move(file)), lines_(lines) {}

  // Records that `value` (now part of the tree) was set by the override `text` ("camera.altitude=5").
  void addOverride(const YAML::Node& value, std::string text);

  SourceLocation at(const YAML::Node& node, const std::string& nodeId = {}) const;
  // A map entry: its key, or its value when an override wrote the value (or made the key, which then
  // has no mark), so that the override is named.
  SourceLocation atEntry(const YAML::Node& key, const YAML::Node& value, const std::string& nodeId = {}) const;

  // An error located at a node or an entry; when an override wrote it, the problem quotes the override.
  Error error(const YAML::Node& node, const std::string& nodeId, const std::string& problem,
              const std::string& fix) const;
  Error entryError(const YAML::Node& key, const YAML::Node& value, const std::string& nodeId,
                   const std::string& problem, const std::string& fix) const;

 private:
  const std::string* overrideOf(const YAML::Node& node) const;  // the override that wrote node, if any
  const YAML::Node& entryAnchor(const YAML::Node& key, const YAML::Node& value) const;

  std::string file_;
  bool lines_;
  std::vector<std::pair<YAML::Node, std::string>> overrides_;
};

// Where --set overrides are reported: not in any file, so no line or column.
inline constexpr const char* kOverrideFile = "--set";

}  // namespace strata::loader
