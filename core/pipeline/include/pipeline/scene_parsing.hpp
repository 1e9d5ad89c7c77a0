#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <strata/host/pipeline.hpp>
#include <strata/host/scene_settings.hpp>

#include "pipeline/source_map.hpp"

// The scene's sections of a pipeline (body, camera, cache, colour, date), read against their declarations
// (strata/host/scene_settings.hpp) by the code that reads node parameters. Every section is optional, and so is
// every key in one: what is absent keeps its default.
namespace strata::loader {

// The values a map of declared parameters (a section's, a camera path's keyframe) gives, each parsed against its
// declaration; `what` names the map in messages ("camera", "keyframe 2"). A relative path resolves against
// `directory`. Throws strata::Error at the value, or at an unknown key with a did-you-mean.
ParameterSet parseSection(const YAML::Node& value, const std::vector<ParameterDeclaration>& parameters,
                          const std::string& what, const SourceMap& source, const std::filesystem::path& directory);

// The same for a map that may hold other keys too: reads the declared ones it has and checks no key.
ParameterSet parseDeclared(const YAML::Node& value, const std::vector<ParameterDeclaration>& parameters,
                           const std::string& what, const SourceMap& source, const std::filesystem::path& directory);

std::vector<std::string> namesOf(const std::vector<ParameterDeclaration>& parameters);

// Reads every scene section `root` has into `pipeline`.
void readScene(const YAML::Node& root, const SourceMap& source, Pipeline& pipeline);

// The camera a validated set of camera parameters gives (the scene's `camera:`, a camera path's keyframe), its
// longitude wrapped into [-180, 180): longitudes name the same meridian modulo 360, and one range keeps later
// arithmetic simple.
Camera cameraOf(const ParameterSet& parameters);

}  // namespace strata::loader
