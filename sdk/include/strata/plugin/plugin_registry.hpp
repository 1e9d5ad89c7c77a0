#pragma once
#include <filesystem>
#include <map>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/plugin/plugin.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The node types and projections known to an engine: the built-in projections, those of every plugin
// module loaded, plus any added in code.
class PluginRegistry : public PluginRegistrar {
 public:
  PluginRegistry();  // holds the built-in projections

  struct Module {
    std::filesystem::path file;
    std::string name;
    std::string version;
  };

  // Adds a node type; a type registered already keeps its first declaration (so directories earlier on
  // the plugin path override later ones). Throws strata::Error if the declaration is malformed.
  void add(NodeTypeDeclaration declaration) override;
  // Adds a projection type, with the same first-wins rule; a +proj= name already claimed by another
  // type stays with that type.
  void addProjection(ProjectionDeclaration declaration) override;
  // Loads one plugin module. Throws strata::Error naming the file when it cannot be opened, has no entry
  // point, or was built for another plugin ABI version.
  void loadModule(const std::filesystem::path& file);
  // Loads every "strata-*.so" in each directory (missing directories are skipped); the first module to
  // provide a type wins, so earlier directories override later ones.
  void loadDirectories(const std::vector<std::filesystem::path>& directories);

  const NodeTypeDeclaration* find(const std::string& type) const;
  std::vector<const NodeTypeDeclaration*> types() const;  // sorted by type name
  const std::vector<Module>& modules() const { return modules_; }

  const ProjectionDeclaration* findProjection(const std::string& type) const;
  // The projection type that recognises a +proj= name, or nullptr.
  const ProjectionDeclaration* projectionForProjName(const std::string& projName) const;
  std::vector<const ProjectionDeclaration*> projections() const;  // sorted by type name

 private:
  std::map<std::string, NodeTypeDeclaration> types_;
  std::map<std::string, ProjectionDeclaration> projections_;
  std::map<std::string, std::string> projNames_;  // +proj= name -> projection type
  std::vector<Module> modules_;
  std::string loadingModule_;  // set while a module registers, for messages
};

// Where plugins are looked for: each entry of $STRATA_PLUGIN_PATH (colon-separated), then the plugin
// directory beside the running program (<bin>/../lib/strata/plugins), then the one beside the
// libstrata_core it links (<lib>/strata/plugins: a host application built against an install finds that
// install's plugins, wherever it was moved), then the directory Strata was configured to install into.
std::vector<std::filesystem::path> defaultPluginDirectories();

}  // namespace strata
STRATA_EXPORTS_END
