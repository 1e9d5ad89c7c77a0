// The projection half of the plugin registry: built-in projections first, then those plugins add.
#include <strata/plugin/plugin_registry.hpp>

#include "projection/builtin_projections.hpp"

namespace strata {

PluginRegistry::PluginRegistry() {
  for (ProjectionDeclaration& declaration : builtinProjections()) addProjection(std::move(declaration));
}

void PluginRegistry::addProjection(ProjectionDeclaration declaration) {
  SourceLocation where{loadingModule_.empty() ? std::string("(registered in code)") : loadingModule_};
  if (declaration.type.empty() || !declaration.create)
    throw Error(where, "a projection declaration needs a type name and a factory",
                "set ProjectionDeclaration::type and ::create");
  if (projections_.contains(declaration.type)) return;  // first wins, as for node types
  for (const std::string& projName : declaration.projNames) projNames_.try_emplace(projName, declaration.type);
  std::string type = declaration.type;
  projections_.emplace(std::move(type), std::move(declaration));
}

const ProjectionDeclaration* PluginRegistry::findProjection(const std::string& type) const {
  auto found = projections_.find(type);
  return found == projections_.end() ? nullptr : &found->second;
}

const ProjectionDeclaration* PluginRegistry::projectionForProjName(const std::string& projName) const {
  auto found = projNames_.find(projName);
  return found == projNames_.end() ? nullptr : findProjection(found->second);
}

std::vector<const ProjectionDeclaration*> PluginRegistry::projections() const {
  std::vector<const ProjectionDeclaration*> all;
  for (const auto& [type, declaration] : projections_) all.push_back(&declaration);
  return all;
}

}  // namespace strata
