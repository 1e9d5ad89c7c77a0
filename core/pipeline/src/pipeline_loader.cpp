// Reads a pipeline file. The format, version 1:
//
//   strata: 1                                  # required: the format version; only 1 exists
//   body: {name: Earth, radius: 6371000}       # optional: the scene's sections, declared in
//   camera: {lon: 10, lat: 20, altitude: 2e7}  #   strata/host/scene_settings.hpp (`strata plugins --describe
//   cache: {budget: 256}                       #   scene`, docs/reference/scene.md)
//   date: 2004-06-15
//   colour: {config: my.ocio}
//   nodes:                                     # required: node id -> node (node_parsing.hpp)
//     relief:  {type: source.gdal, path: egm96_15.gtx, kind: height, scale: 300}
//     terrain: {type: geometry.icosahedral, height: relief}
//     frame:   {type: output.image, geometry: terrain, surface: [relief]}
//
// or, for a scene of several bodies, `bodies:` in place of `body:` and `nodes:` (scene_bodies.hpp):
//   bodies:
//     earth: {pipeline: day_night.yaml}
//     moon:  {pipeline: moon.yaml, orbit: moon}
//
// Steps, each of which may throw strata::Error with the file, line and column and a fix: parse the YAML;
// apply the --set overrides to the tree (overrides.hpp); check the top-level keys; read the version,
// body and camera; read the scene's bodies' pipelines, or each node on its own; check how the nodes connect and order
// them (graph_checks.hpp). In every map a key may appear only once, and an unknown key gets a did-you-mean.
#include <utility>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "graph_checks.hpp"
#include "pipeline/overrides.hpp"
#include "pipeline/scene_parsing.hpp"
#include "pipeline/text_file.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"
#include "pipeline_document.hpp"
#include "scene_bodies.hpp"

namespace strata {
namespace {

using loader::SourceMap;

constexpr std::int64_t kFormatVersion = 1;
// "strata", the scene's sections and "nodes", in the order a pipeline writes them.
std::vector<std::string> topLevelKeys() {
  std::vector<std::string> keys{"strata"};
  for (const SceneSection& section : sceneSections()) keys.push_back(section.name);
  keys.push_back("nodes");
  return keys;
}

void requireRootMap(const YAML::Node& root, const SourceMap& source) {
  if (root.IsMap()) return;
  const std::string problem =
      root.IsNull() ? "the pipeline is empty" : "a pipeline must be a map of keys, got " + loader::describe(root);
  throw source.error(root, {}, problem, "start it with `strata: 1` and a `nodes:` map; see pipelines/demo.yaml");
}

int parseVersion(const YAML::Node& root, const SourceMap& source) {
  const YAML::Node value = root["strata"];
  if (!value)
    throw source.error(root, {}, "the pipeline has no 'strata' format version", "add `strata: 1` as its first line");
  const std::int64_t version = loader::readInteger(value, {source, "'strata' (the format version)", {}});
  if (version != kFormatVersion)
    throw source.error(value, {},
                       "unsupported format version " + std::to_string(version) + "; this Strata reads version 1",
                       "write `strata: 1` and the rest of the file in format 1");
  return static_cast<int>(version);
}

std::vector<NodeDescription> parseNodes(const YAML::Node& root, const loader::NodeContext& context) {
  const YAML::Node nodes = root["nodes"];
  if (!nodes)
    throw context.source.error(root, {}, "the pipeline has no 'nodes'",
                               "add a `nodes:` map from node ids to nodes, e.g. `frame: {type: output.image, ...}`");
  if (!nodes.IsMap())
    throw context.source.error(nodes, {},
                               "'nodes' must be a map from node ids to nodes, got " + loader::describe(nodes),
                               "write each node under `nodes:` as `id: {type: ..., ...}`");
  loader::requireUniqueKeys(nodes, context.source, "node id");
  std::vector<loader::ParsedNode> parsed;
  for (const auto& entry : nodes) parsed.push_back(loader::parseNode(entry.first, entry.second, context));
  return loader::connectNodes(std::move(parsed), nodes, context.source);
}

// After the overrides, the document is only read: through a const node, since yaml-cpp's non-const
// operator[] adds the keys it looks up.
Pipeline readDocument(const YAML::Node& root, const SourceMap& source, const loader::DocumentOrigin& origin,
                      const PluginRegistry& registry) {
  loader::requireUniqueKeys(root, source, "key");
  loader::requireKnownKeys(root, topLevelKeys(), source, "the pipeline");
  Pipeline pipeline;
  pipeline.file = origin.file;
  pipeline.name = origin.name;
  pipeline.directory = origin.directory;
  pipeline.version = parseVersion(root, source);
  loader::readScene(root, source, pipeline);
  loader::readSceneBodies(root, source, registry, pipeline);
  if (pipeline.bodies.empty()) pipeline.nodes = parseNodes(root, {source, registry, origin.directory});
  return pipeline;
}

}  // namespace

Pipeline loader::readPipelineDocument(YAML::Node root, const DocumentOrigin& origin,
                                      const std::vector<std::string>& overrides, const PluginRegistry& registry) {
  SourceMap source(origin.name, origin.lines);
  requireRootMap(root, source);
  applyOverrides(root, overrides, source);
  return readDocument(root, source, origin, registry);
}

Pipeline parsePipeline(const std::string& text, const std::filesystem::path& fileName,
                       const std::vector<std::string>& overrides, const PluginRegistry& registry) {
  const std::filesystem::path directory =
      fileName.empty() ? std::filesystem::current_path() : std::filesystem::absolute(fileName).parent_path();
  return loader::readPipelineDocument(loader::parseYamlText(text, fileName.string()),
                                      {fileName, fileName.string(), directory}, overrides, registry);
}

Pipeline loadPipeline(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                      const PluginRegistry& registry) {
  return parsePipeline(loader::readTextFile(file, "pipeline", "pipelines/ holds ready-made pipelines"), file, overrides,
                       registry);
}

const NodeDescription* Pipeline::find(const std::string& id) const {
  for (const auto& node : nodes)
    if (node.id == id) return &node;
  return nullptr;
}

}  // namespace strata
