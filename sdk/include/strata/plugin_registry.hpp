#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <strata/plugin.hpp>

namespace strata {

// The node types known to an engine: those of every plugin module loaded, plus any added in code.
class PluginRegistry : public PluginRegistrar {
 public:
  struct Module {
    std::filesystem::path file;
    std::string name;
    std::string version;
  };

  // Adds a node type; a type registered already keeps its first declaration (so directories earlier on
  // the plugin path override later ones). Throws strata::Error if the declaration is malformed.
  void add(NodeTypeDeclaration declaration) override;
  // Loads one plugin module. Throws strata::Error naming the file when it cannot be opened, has no entry
  // point, or was built for another plugin ABI version.
  void loadModule(const std::filesystem::path& file);
  // Loads every "strata-*.so" in each directory (missing directories are skipped); the first module to
  // provide a type wins, so earlier directories override later ones.
  void loadDirectories(const std::vector<std::filesystem::path>& directories);

  const NodeTypeDeclaration* find(const std::string& type) const;
  std::vector<const NodeTypeDeclaration*> types() const;  // sorted by type name
  const std::vector<Module>& modules() const { return modules_; }

 private:
  std::map<std::string, NodeTypeDeclaration> types_;
  std::vector<Module> modules_;
  std::string loadingModule_;  // set while a module registers, for messages
};

// Where plugins are looked for: each entry of $STRATA_PLUGIN_PATH (colon-separated), then the plugin
// directory beside the running program (<bin>/../lib/strata/plugins), then the install directory.
std::vector<std::filesystem::path> defaultPluginDirectories();

}  // namespace strata
