#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata::loader {

// Where a pipeline's document came from: a file (loadPipeline, parsePipeline) or code (PipelineBuilder).
struct DocumentOrigin {
  std::filesystem::path file;       // empty when built in code
  std::string name;                 // what error messages call it: the file's path, or the builder's name
  std::filesystem::path directory;  // absolute; relative paths in the document resolve against it
  bool lines = true;                // whether its YAML nodes carry lines and columns: not when built in code
};

// Applies the --set `overrides` to the document's tree, then validates and orders it (pipeline_loader.cpp
// lists the steps). Throws strata::Error located in `origin`.
Pipeline readPipelineDocument(YAML::Node root, const DocumentOrigin& origin, const std::vector<std::string>& overrides,
                              const PluginRegistry& registry);

}  // namespace strata::loader
