// A pipeline built in code: the document a pipeline file would hold, as a yaml-cpp tree whose scalars are
// tagged as plain (unquoted) ones, so that the loader reads each value exactly as it reads one in a file.
#include <strata/host/pipeline_builder.hpp>

#include <type_traits>
#include <utility>

#include <strata/error.hpp>

#include "pipeline/overrides.hpp"
#include "pipeline_document.hpp"

namespace strata {

struct PipelineBuilder::Document {
  YAML::Node root{YAML::NodeType::Map};
};

namespace {

// yaml-cpp gives a plain scalar in a file the non-specific tag "?"; one made in code has none.
YAML::Node plainScalar(const std::string& text) {
  YAML::Node scalar(text);
  scalar.SetTag("?");
  return scalar;
}

template <class Element>
YAML::Node sequenceOf(const std::vector<Element>& elements) {
  YAML::Node sequence(YAML::NodeType::Sequence);
  for (const Element& element : elements) sequence.push_back(plainScalar(formatValue(element)));
  return sequence;
}

YAML::Node documentValue(const PipelineValue& value) {
  return std::visit(
      [](const auto& held) -> YAML::Node {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, std::vector<double>> || std::is_same_v<T, std::vector<std::string>>)
          return sequenceOf(held);
        else
          return plainScalar(formatValue(held));
      },
      value);
}

Error pathError(const std::string& name, const std::string& path, const std::string& problem) {
  return Error(SourceLocation{name}, "cannot set '" + path + "' in the pipeline built in code: " + problem,
               "give dot-separated keys from the top of the document, e.g. nodes.relief.scale");
}

}  // namespace

PipelineBuilder::PipelineBuilder(std::string name, const std::filesystem::path& directory)
    : name_(std::move(name)),
      directory_(std::filesystem::absolute(directory.empty() ? std::filesystem::current_path() : directory)),
      document_(std::make_unique<Document>()) {
  set("strata", std::int64_t{1});  // the format version this Strata reads and writes
}

PipelineBuilder::~PipelineBuilder() = default;

PipelineBuilder::PipelineBuilder(const PipelineBuilder& other)
    : name_(other.name_), directory_(other.directory_), document_(std::make_unique<Document>()) {
  document_->root.reset(YAML::Clone(other.document_->root));  // yaml-cpp nodes share their data when copied
}

PipelineBuilder& PipelineBuilder::operator=(const PipelineBuilder& other) {
  if (this != &other) {
    name_ = other.name_;
    directory_ = other.directory_;
    document_->root.reset(YAML::Clone(other.document_->root));
  }
  return *this;
}

PipelineBuilder& PipelineBuilder::set(const std::string& path, PipelineValue value) {
  const std::vector<std::string> keys = loader::splitKeyPath(path);
  for (const std::string& key : keys)
    if (key.empty()) throw pathError(name_, path, "it has an empty key");
  assign(keys, value, path);
  return *this;
}

// A node's id and entry names are keys as given, dots and all, for the loader to judge as it judges a
// file's (an id must be an identifier).
PipelineBuilder& PipelineBuilder::node(const std::string& id, const std::string& type,
                                       const std::vector<std::pair<std::string, PipelineValue>>& entries) {
  assign({"nodes", id, "type"}, type, "nodes." + id + ".type");
  for (const auto& [key, value] : entries) assign({"nodes", id, key}, value, "nodes." + id + "." + key);
  return *this;
}

// Writes `value` at `keys`, making the maps on the way; `path` names the place in messages.
void PipelineBuilder::assign(const std::vector<std::string>& keys, const PipelineValue& value,
                             const std::string& path) {
  YAML::Node map = document_->root;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    YAML::Node child = map[keys[i]];
    if (!child.IsDefined() || child.IsNull()) child = YAML::Node(YAML::NodeType::Map);
    if (!child.IsMap()) throw pathError(name_, path, "'" + keys[i] + "' holds a value, not a map of keys");
    map.reset(child);  // not `map = child`: yaml-cpp's assignment would overwrite the node map refers to
  }
  map[keys.back()] = documentValue(value);
}

const std::string& PipelineBuilder::name() const { return name_; }

const std::filesystem::path& PipelineBuilder::directory() const { return directory_; }

std::string PipelineBuilder::yaml() const {
  YAML::Emitter emitter;
  emitter << document_->root;
  return std::string(emitter.c_str()) + "\n";
}

Pipeline PipelineBuilder::build(const PluginRegistry& registry, const std::vector<std::string>& overrides) const {
  return loader::readPipelineDocument(YAML::Clone(document_->root), {{}, name_, directory_, false}, overrides,
                                      registry);
}

}  // namespace strata
