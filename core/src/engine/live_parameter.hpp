#pragma once
#include <optional>
#include <string>

#include <strata/pipeline.hpp>
#include <strata/plugin_registry.hpp>

namespace strata {

// The id of the node whose parameter `override` ("nodes.ID.NAME=VALUE", as --set) changes, when that
// parameter is declared live (ParameterDeclaration::live) for the node's type in `pipeline`; none for any
// other override (the camera, a node's inputs or type, a parameter that rebuilds what it made), which needs
// the pipeline loaded again.
std::optional<std::string> liveParameterNode(const std::string& override, const Pipeline& pipeline,
                                             const PluginRegistry& registry);

}  // namespace strata
