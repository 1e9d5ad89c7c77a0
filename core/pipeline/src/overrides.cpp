#include "pipeline/overrides.hpp"

#include <utility>

#include <strata/host/scene_settings.hpp>

#include "pipeline/suggestions.hpp"

namespace strata::loader {
namespace {

struct Override {
  std::string text;  // as given, for messages
  std::vector<std::string> path;
  std::string value;
};

Error overrideError(const Override& entry, const std::string& problem, const std::string& fix) {
  return Error(SourceLocation{kOverrideFile}, "cannot apply --set '" + entry.text + "': " + problem, fix);
}

Override parseOverride(const std::string& text) {
  const std::size_t equals = text.find('=');
  Override entry{text, {}, {}};
  const std::string fix = "write --set PATH=VALUE, e.g. --set camera.altitude=5000";
  if (equals == std::string::npos) throw overrideError(entry, "it has no '='", fix);
  entry.path = splitKeyPath(text.substr(0, equals));
  entry.value = text.substr(equals + 1);
  for (const auto& key : entry.path)
    if (key.empty()) throw overrideError(entry, "PATH has an empty key", fix);
  return entry;
}

YAML::Node parseValue(const Override& entry) {
  try {
    return YAML::Load(entry.value);
  } catch (const YAML::Exception& exception) {
    throw overrideError(
        entry, "VALUE is not valid YAML: " + exception.msg,
        "quote the override for the shell and check its brackets, e.g. --set 'nodes.frame.surface=[a, b]'");
  }
}

std::string joinedPath(const Override& entry, std::size_t last) {
  std::string path;
  for (std::size_t i = 0; i <= last; ++i) path += (i ? "." : "") + entry.path[i];
  return path;
}

// `--set a.b.c=5` where a has no b: the same change written where the path ends, `--set a.b={c: 5}`.
std::string rewrittenAt(const Override& entry, std::size_t missing) {
  std::string value = entry.value;
  for (std::size_t i = entry.path.size() - 1; i > missing; --i) value = "{" + entry.path[i] + ": " + value + "}";
  return joinedPath(entry, missing) + "=" + value;
}

std::vector<std::string> keysOf(const YAML::Node& map) {
  std::vector<std::string> keys;
  for (const auto& entry : map)
    if (entry.first.IsScalar()) keys.push_back(entry.first.Scalar());
  return keys;
}

// A section of the scene whose keys are declared (`camera`, not the scalar `date`): one a pipeline leaves
// out may be set key by key, `--set body.radius=3389500`, as if it were written empty.
bool isSceneSection(const std::string& key) {
  const SceneSection* section = findSceneSection(key);
  return section && section->form != SceneSection::Form::Value;
}

// The map that holds the last key of the override's path.
YAML::Node parentMap(const YAML::Node& root, const Override& entry) {
  YAML::Node map = root;
  for (std::size_t i = 0; i + 1 < entry.path.size(); ++i) {
    // Looked up through a const node: yaml-cpp's non-const operator[] would add the key if missing.
    if (i == 0 && !std::as_const(map)[entry.path[i]] && isSceneSection(entry.path[i]))
      map[entry.path[i]] = YAML::Node(YAML::NodeType::Map);
    const YAML::Node child = std::as_const(map)[entry.path[i]];
    if (!child)
      throw overrideError(entry,
                          "the pipeline has no '" + joinedPath(entry, i) + "'" + didYouMean(entry.path[i], keysOf(map)),
                          "add it to the file, or set it whole: --set '" + rewrittenAt(entry, i) + "'");
    if (!child.IsMap())
      throw overrideError(entry, "'" + joinedPath(entry, i) + "' is not a map, so it has no keys to set",
                          "set '" + joinedPath(entry, i) + "' itself: --set '" + joinedPath(entry, i) + "=VALUE'");
    map.reset(child);  // not `map = child`: yaml-cpp's assignment would overwrite the node map refers to
  }
  return map;
}

}  // namespace

std::vector<std::string> splitKeyPath(const std::string& path) {
  std::vector<std::string> keys;
  std::size_t start = 0;
  for (std::size_t dot; (dot = path.find('.', start)) != std::string::npos; start = dot + 1)
    keys.push_back(path.substr(start, dot - start));
  keys.push_back(path.substr(start));
  return keys;
}

void applyOverrides(YAML::Node& root, const std::vector<std::string>& overrides, SourceMap& source) {
  for (const auto& text : overrides) {
    const Override entry = parseOverride(text);
    YAML::Node value = parseValue(entry);
    YAML::Node map = parentMap(root, entry);
    map[entry.path.back()] = value;
    source.addOverride(value, entry.text);  // after the assignment, which gives a null value its node
  }
}

}  // namespace strata::loader
