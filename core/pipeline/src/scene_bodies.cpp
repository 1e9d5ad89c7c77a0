// A scene of several bodies: `bodies:`, each entry a body's own pipeline file and where the body stands.
#include "scene_bodies.hpp"

#include <glm/geometric.hpp>
#include <strata/log.hpp>
#include <strata/named_bodies.hpp>

#include "pipeline/scene_parsing.hpp"
#include "pipeline/scene_placement.hpp"
#include "pipeline/suggestions.hpp"
#include "pipeline/text_file.hpp"
#include "pipeline/yaml_maps.hpp"

namespace strata::loader {
namespace {

// A scene of several bodies draws every surface through its bodies' pipelines: a `body:`, `nodes:` or
// `atmosphere:` of its own would belong to none of them.
void refuseOwnSurface(const YAML::Node& root, const SourceMap& source) {
  for (const char* key : {"body", "nodes", "atmosphere"})
    if (const YAML::Node value = root[key])
      throw source.error(
          value, {},
          std::string("a scene of several bodies (bodies:) draws each by its own pipeline; its own '") + key +
              "' would belong to none of them",
          std::string("move '") + key + "' into a body's pipeline file and name that file under bodies:");
}

SceneBody readBody(const YAML::Node& key, const YAML::Node& value, const SourceMap& source,
                   const PluginRegistry& registry, const Pipeline& scene) {
  SceneBody body{.id = keyText(key, value, source), .where = source.at(key)};
  const ParameterSet parameters =
      parseSection(value, sceneBodyParameters().declarations(), "bodies." + body.id, source, scene.directory);
  if (!parameters.has("pipeline"))
    throw source.error(key, {}, "the body '" + body.id + "' names no pipeline to draw it",
                       "add `pipeline: earth.yaml`: a pipeline file with the body and its nodes");
  const SceneBodySettings settings = sceneBodyParameters().read(parameters);
  // Looked at before it is read as a pipeline: a scene that named itself would be read without end.
  const std::string text = readTextFile(settings.pipeline, "pipeline", "pipelines/ holds ready-made pipelines");
  if (const YAML::Node root = parseYamlText(text, settings.pipeline.string()); root.IsMap() && root["bodies"])
    throw Error(parameters.where("pipeline"),
                "'" + settings.pipeline.string() + "' is a scene of several bodies itself",
                "name a pipeline that draws one body, with body: and nodes:");
  body.pipeline = parsePipeline(text, settings.pipeline, {}, registry);
  body.orbit = settings.orbit;
  body.position = {settings.position[0], settings.position[1], settings.position[2]};
  return body;
}

// The first body sets the scene's axes and stands at its origin; an orbit needs the scene's date, and the
// Moon's is about the Earth, which must be the first body.
void checkPlacements(const std::vector<SceneBody>& bodies, const YAML::Node& entries, const SourceMap& source,
                     const Pipeline& scene) {
  const SceneBody& first = bodies.front();
  if (first.orbit != BodyOrbit::Fixed || first.position != glm::dvec3(0.0))
    throw Error(first.where, "the first body, '" + first.id + "', sets the scene's axes and stands at its origin",
                "list first the body the others are placed about (the Earth, for orbit: moon), without orbit or "
                "position");
  for (const SceneBody& body : bodies) {
    if (body.orbit != BodyOrbit::Moon) continue;
    const SourceLocation where = source.at(entries[body.id]["orbit"]);
    if (!scene.date)
      throw Error(where, "orbit: moon places the Moon where it stands at the scene's date, and the scene has none",
                  "give the scene a date (date: 2024-03-20T18:00Z), or place the body by position");
    if (findNamedBody(first.pipeline.body.name) != findNamedBody("Earth"))
      throw Error(
          where,
          "orbit: moon is the Moon's orbit about the Earth, and the first body is '" + first.pipeline.body.name + "'",
          "list the Earth's pipeline first under bodies:");
  }
}

// Bodies are laid over one another by the order their spheres give (SceneFrame), which holds only while the
// spheres stay apart: where two meet at the scene's date, say so.
void warnOfMeetingBodies(const Pipeline& scene) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < scene.bodies.size(); ++j) {
      const SceneBody &a = scene.bodies[i], &b = scene.bodies[j];
      const double apart = glm::length(placementOf(a, scene.date).centre - placementOf(b, scene.date).centre);
      if (apart < a.pipeline.body.radius + b.pipeline.body.radius)
        logWarning(b.where.str() + ": the bodies '" + a.id + "' and '" + b.id + "' meet (their centres lie " +
                       formatValue(ParameterValue(apart)) +
                       " m apart); where both show, the nearer centre's may not "
                       "hide the other as it should",
                   "place them farther apart than their radii together");
    }
}

// The camera's body is one of the scene's; the scene's own body becomes that one's, which hosts measure the
// camera over.
void resolveCameraBody(const YAML::Node& root, const SourceMap& source, Pipeline& scene) {
  const YAML::Node written = root["camera"] ? root["camera"]["body"] : YAML::Node();
  std::vector<std::string> ids;
  for (const SceneBody& body : scene.bodies) ids.push_back(body.id);
  if (scene.bodies.empty()) {
    if (!scene.camera.body.empty())
      throw source.error(written, {},
                         "the camera is placed over the body '" + scene.camera.body +
                             "', but this pipeline draws one body and names none",
                         "leave out the camera's body, or list the scene's bodies under bodies:");
    return;
  }
  if (scene.camera.body.empty()) scene.camera.body = ids.front();
  for (const SceneBody& body : scene.bodies)
    if (body.id == scene.camera.body) {
      scene.body = body.pipeline.body;
      return;
    }
  throw source.error(written, {},
                     "the camera is placed over '" + scene.camera.body + "', which is not a body of the scene" +
                         didYouMean(scene.camera.body, ids),
                     "name one of the bodies: " + quotedList(ids));
}

// Each body sees the scene's sun from where it stands; where the scene places no sun, a body keeps its own.
void giveSceneSun(Pipeline& scene) {
  const std::optional<SubsolarPoint> sun = sceneSun(scene.bodies.front().pipeline.body, scene.date, scene.sun);
  for (SceneBody& body : scene.bodies) {
    body.pipeline.date = scene.date;
    if (sun) body.pipeline.sun = sunOver(*sun, placementOf(body, scene.date));
  }
}

}  // namespace

void readSceneBodies(const YAML::Node& root, const SourceMap& source, const PluginRegistry& registry, Pipeline& scene) {
  const YAML::Node entries = root["bodies"];
  if (entries) {
    refuseOwnSurface(root, source);
    if (!entries.IsMap() || entries.size() == 0)
      throw source.error(entries, {}, "'bodies' must be a map from body ids to bodies",
                         "write each as `earth: {pipeline: earth.yaml}`, the body the others are placed about first");
    requireUniqueKeys(entries, source, "body id");
    for (const auto& entry : entries)
      scene.bodies.push_back(readBody(entry.first, entry.second, source, registry, scene));
    checkPlacements(scene.bodies, entries, source, scene);
    warnOfMeetingBodies(scene);
    giveSceneSun(scene);
  }
  resolveCameraBody(root, source, scene);
}

}  // namespace strata::loader
