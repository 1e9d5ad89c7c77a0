// Reads a camera path file. The format, version 1 (docs/camera-paths.md):
//
//   strata-path: 1                         # required: the format version; only 1 exists
//   keyframes:                             # either keyframes, times in seconds ...
//     - {time: 0, lon: 0, lat: 20, altitude: 2.0e7}
//     - {time: 10, lon: 10, lat: 46, altitude: 5000, heading: 30, tilt: 70}
//   fly_to:                                # ... or a great-circle flight
//     from: {lon: 0, lat: 20, altitude: 2.0e7}
//     to: {lon: 10, lat: 46, altitude: 5000}
//     duration: 10                         # s
//
// Every mistake is a strata::Error with the file, line and column and a fix, as in pipelines.

#include "path_sections.hpp"
#include "pipeline/text_file.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"

namespace strata {
namespace {

using loader::SourceMap;

constexpr std::int64_t kFormatVersion = 1;
const std::vector<std::string> kTopLevelKeys{"strata-path", "keyframes", "fly_to"};
constexpr const char* kExample = "see pipelines/paths/flyin.yaml";

void requireVersion(const YAML::Node& root, const SourceMap& source) {
  if (!root.IsMap())
    throw source.error(root, {}, root.IsNull() ? "the path file is empty" : "a path must be a map of keys",
                       std::string("start it with `strata-path: 1` and a `keyframes:` list; ") + kExample);
  loader::requireUniqueKeys(root, source, "key");
  const YAML::Node value = root["strata-path"];
  if (!value)  // before the keys: a pipeline given as a path is told so, not that 'strata' is unknown
    throw source.error(root, {}, "the file has no 'strata-path' format version",
                       "add `strata-path: 1` as its first line (is this a pipeline, not a path?)");
  loader::requireKnownKeys(root, kTopLevelKeys, source, "a path file");
  const std::int64_t version = loader::readInteger(value, {source, "'strata-path' (the format version)", {}});
  if (version != kFormatVersion)
    throw source.error(value, {},
                       "unsupported path format version " + std::to_string(version) + "; this Strata reads version 1",
                       "write `strata-path: 1` and the rest of the file in format 1");
}

CameraPath readBody(const YAML::Node& root, const SourceMap& source, const Body& body) {
  const YAML::Node keyframes = root["keyframes"], flyTo = root["fly_to"];
  if (keyframes && flyTo)
    throw source.error(flyTo, {}, "a path has either 'keyframes' or 'fly_to', not both",
                       "keep one of them, or write the flight as keyframes");
  if (keyframes) return paths::readKeyframes(keyframes, source);
  if (flyTo) return paths::readFlyTo(flyTo, source, body);
  throw source.error(root, {}, "the path has neither 'keyframes' nor 'fly_to'",
                     std::string("add a `keyframes:` list of cameras or a `fly_to:` map; ") + kExample);
}

}  // namespace

CameraPath parseCameraPath(const std::string& text, const std::filesystem::path& fileName, const Body& body) {
  const SourceMap source(fileName.string());
  const YAML::Node root = loader::parseYamlText(text, fileName.string());
  requireVersion(root, source);
  return readBody(root, source, body);
}

CameraPath readCameraPath(const std::filesystem::path& file, const Body& body) {
  return parseCameraPath(loader::readTextFile(file, "camera path", "pipelines/paths/ holds sample paths"), file, body);
}

}  // namespace strata
