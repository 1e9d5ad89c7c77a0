#pragma once
#include <filesystem>
#include <string>

#include <strata/host/scene_settings.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/plugin_registry.hpp>

// How declarations read to people: in the terminal (`strata plugins --describe`) and as the Markdown of
// docs/reference/ (`strata plugins --reference DIR`), both from the declarations alone.
namespace strata::cli {

// "default 45", "optional" or "required".
std::string defaultText(const ParameterDeclaration& parameter);
// "texels|metres", "[0, 90]", "(0, inf]" or "".
std::string rangeText(const ParameterDeclaration& parameter);

// The Markdown page of a node type, and of the scene's sections.
std::string referencePage(const NodeTypeDeclaration& type);
std::string scenePage(const std::vector<SceneSection>& sections);
// The index: every node type and projection of `registry`, and the scene.
std::string referenceIndex(const PluginRegistry& registry);

// Writes the index (README.md), scene.md and one page per node type into `directory`, replacing what the
// generator wrote before; throws strata::Error, with nothing written, when the folder holds any other file.
void writeReference(const PluginRegistry& registry, const std::filesystem::path& directory);

}  // namespace strata::cli
