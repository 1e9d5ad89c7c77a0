#pragma once
#include <yaml-cpp/yaml.h>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "pipeline/source_map.hpp"

namespace strata::loader {

// Reads a scene of several bodies (`bodies:`) into `scene`, whose date, sun and camera are read already: each
// entry's pipeline loaded from its file, given the scene's date and the scene's sun turned into its axes; the
// scene's body made the camera's. Checks the camera's `body`, with or without `bodies:`. Throws strata::Error at
// the entry, the value or the camera's `body`, with a fix; an error in a body's file names that file.
void readSceneBodies(const YAML::Node& root, const SourceMap& source, const PluginRegistry& registry, Pipeline& scene);

}  // namespace strata::loader
