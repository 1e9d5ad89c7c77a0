#pragma once
#include <optional>
#include <string>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/parameter.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata {

// A node's parameters with one live parameter changed.
struct LiveChange {
  std::string node;
  ParameterSet parameters;
};

// What `override` ("nodes.ID.NAME=VALUE", as --set) makes of its node's parameters in `pipeline`, when
// NAME is declared live (ParameterDeclaration::live) for the node's type: its value read against the
// declaration as loading the pipeline with the override would read it, without the file. None for any other
// override (the camera, a node's inputs or type, a parameter that rebuilds what it made), which needs the
// pipeline loaded again. Throws strata::Error at --set for a value the declaration refuses.
std::optional<LiveChange> liveChange(const std::string& override, const Pipeline& pipeline,
                                     const PluginRegistry& registry);

}  // namespace strata
