#include "pipeline/scene_parsing.hpp"

#include <cmath>

#include "named_body.hpp"
#include "pipeline/parameter_parsing.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"

namespace strata::loader {
namespace {

// `what: {first: default, second: default}`, from the declarations: how a map of them is written.
std::string exampleMap(const std::string& what, const std::vector<ParameterDeclaration>& parameters) {
  std::string example;
  for (const ParameterDeclaration& parameter : parameters)
    if (parameter.defaultValue && example.size() < 40)
      example += (example.empty() ? "" : ", ") + parameter.name + ": " + formatValue(*parameter.defaultValue);
  return what + ": {" + example + "}";
}

void requireMap(const YAML::Node& map, const std::vector<ParameterDeclaration>& parameters, const std::string& what,
                const SourceMap& source) {
  if (!map.IsMap())
    throw source.error(map, {}, "'" + what + "' must be a map, got " + describe(map),
                       "write it as " + exampleMap(what, parameters));
  requireUniqueKeys(map, source, "key");
  requireKnownKeys(map, namesOf(parameters), source, what);
}

// The parameters the scene's section `name` gives; none where the pipeline leaves it out.
ParameterSet readSection(const YAML::Node& root, const std::string& name, const SourceMap& source,
                         const std::filesystem::path& directory) {
  const SceneSection& section = *findSceneSection(name);
  const YAML::Node value = root[section.name];
  if (!value) return {};
  if (section.form == SceneSection::Form::Map)
    return parseSection(value, section.parameters, section.name, source, directory);
  const ParameterDeclaration& parameter = section.parameters.front();
  ParameterSet set;
  set.set(parameter.name,
          parseParameter(value, parameter, {source, "the scene's '" + section.name + "'", {}}, directory),
          source.at(value));
  return set;
}

// The scene's `atmosphere:`. Throws strata::Error at it where its aerosols would scatter more than they take
// from the light: extinction is scattering plus absorption.
Atmosphere atmosphereOf(const YAML::Node& root, const SourceMap& source, const std::filesystem::path& directory) {
  Atmosphere air = atmosphereParameters().read(readSection(root, "atmosphere", source, directory));
  air.where = source.at(root["atmosphere"]);
  if (air.mieExtinction < air.mieScattering)
    throw Error(air.where, "the aerosols' extinction (mie_extinction) is less than their scattering",
                "give mie_extinction at least mie_scattering: the Earth's haze absorbs a tenth, mie_scattering / 0.9");
  return air;
}

double wrapLongitude(double lon) {
  const double wrapped = std::fmod(lon + 180.0, 360.0);
  return (wrapped < 0.0 ? wrapped + 360.0 : wrapped) - 180.0;
}

}  // namespace

ParameterSet parseSection(const YAML::Node& value, const std::vector<ParameterDeclaration>& parameters,
                          const std::string& what, const SourceMap& source, const std::filesystem::path& directory) {
  requireMap(value, parameters, what, source);
  return parseDeclared(value, parameters, what, source, directory);
}

ParameterSet parseDeclared(const YAML::Node& value, const std::vector<ParameterDeclaration>& parameters,
                           const std::string& what, const SourceMap& source, const std::filesystem::path& directory) {
  ParameterSet set;
  for (const ParameterDeclaration& parameter : parameters)
    if (const YAML::Node entry = value[parameter.name])
      set.set(parameter.name,
              parseParameter(entry, parameter, {source, what + " '" + parameter.name + "'", {}}, directory),
              source.at(entry));
  return set;
}

void readScene(const YAML::Node& root, const SourceMap& source, Pipeline& pipeline) {
  const std::filesystem::path& directory = pipeline.directory;
  pipeline.body = bodyOf(readSection(root, "body", source, directory));
  pipeline.camera = cameraOf(readSection(root, "camera", source, directory));
  pipeline.cache = cacheParameters().read(readSection(root, "cache", source, directory));
  pipeline.cache.where = root["cache"] ? source.at(root["cache"]) : SourceLocation{pipeline.name};
  pipeline.colour = colourParameters().read(readSection(root, "colour", source, directory));
  if (const YAML::Node colour = root["colour"])
    if (const YAML::Node config = colour["config"]) pipeline.colour.where = source.at(config);
  pipeline.date = dateParameters().read(readSection(root, "date", source, directory)).date;
  if (root["sun"]) {
    SubsolarPoint sun = sunParameters().read(readSection(root, "sun", source, directory));
    sun.lon = wrapLongitude(sun.lon);
    pipeline.sun = sun;
  }
  if (root["atmosphere"]) pipeline.atmosphere = atmosphereOf(root, source, directory);
}

Camera cameraOf(const ParameterSet& parameters) {
  Camera camera = cameraParameters().read(parameters);
  camera.lon = wrapLongitude(camera.lon);
  return camera;
}

std::vector<std::string> namesOf(const std::vector<ParameterDeclaration>& parameters) {
  std::vector<std::string> names;
  for (const ParameterDeclaration& parameter : parameters) names.push_back(parameter.name);
  return names;
}

}  // namespace strata::loader
