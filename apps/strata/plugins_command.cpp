#include <cstdio>
#include <memory>

#include <strata/plugin/node_type.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "command_options.hpp"
#include "commands.hpp"
#include "parameter_reference.hpp"

namespace strata::cli {
namespace {

constexpr const char* kScene = "scene";  // what --describe calls the scene's settings

void list(const PluginRegistry& registry) {
  for (const NodeTypeDeclaration* type : registry.types())
    std::printf("%-24s %-10s %s\n", type->type.c_str(), toString(type->category), type->summary.c_str());
  std::printf("\nprojections (recognised from a raster's CRS by its +proj= name):\n");
  for (const ProjectionDeclaration* projection : registry.projections()) {
    std::string projNames;
    for (const std::string& name : projection->projNames) projNames += (projNames.empty() ? "" : ",") + name;
    std::printf("%-24s %s (+proj=%s)\n", projection->type.c_str(), projection->summary.c_str(), projNames.c_str());
  }
  std::printf("\nmodules:\n");
  for (const auto& module : registry.modules())
    std::printf("  %s %s  %s\n", module.name.c_str(), module.version.c_str(), module.file.c_str());
  std::printf(
      "\n`strata plugins --describe TYPE` shows a type's inputs and parameters; `--describe scene` the "
      "scene's settings (body, camera, cache, date, colour).\n");
}

void describeParameters(const std::vector<ParameterDeclaration>& parameters) {
  if (parameters.empty()) std::printf("  (none)\n");
  for (const ParameterDeclaration& p : parameters)
    std::printf("  %-17s %-9s %-14s %-16s %-7s %s%s\n", p.name.c_str(), toString(p.type), defaultText(p).c_str(),
                rangeText(p).c_str(), p.units.c_str(), p.live ? "(live) " : "", p.doc.c_str());
}

void describe(const NodeTypeDeclaration& type) {
  std::printf("%s (%s)\n  %s\n\ninputs:\n", type.type.c_str(), toString(type.category), type.summary.c_str());
  if (type.inputs.empty()) std::printf("  (none)\n");
  for (const PortDeclaration& port : type.inputs) {
    std::string kinds;
    for (LayerKind kind : port.kinds) kinds += (kinds.empty() ? " " : "|") + std::string(toString(kind));
    std::printf("  %-16s %s%s%s%s  %s\n", port.name.c_str(), toString(port.type), kinds.c_str(),
                port.list ? ", list" : "", port.optional ? ", optional" : "", port.doc.c_str());
  }
  std::printf("\nparameters:\n");
  describeParameters(type.parameters);
  std::printf("\n(live): changes take effect in the next frame with nothing rebuilt (Engine::set, the viewer)\n");
}

void describeScene() {
  std::printf("scene: the pipeline's own settings beside `nodes:`, each section and key optional\n");
  for (const SceneSection& section : sceneSections()) {
    std::printf("\n%s%s: %s\n", section.name.c_str(), section.formNote(), section.doc.c_str());
    describeParameters(section.parameters);
  }
}

// `--describe NAME`: the scene's settings, or a node type's.
void describe(const PluginRegistry& registry, const std::string& name) {
  if (name == kScene) return describeScene();
  const NodeTypeDeclaration* type = registry.find(name);
  if (!type)
    throw Error({"strata plugins"}, "no node type '" + name + "' is registered",
                "run `strata plugins` to list the types (`--describe scene` for the scene's settings), or add a "
                "plugin directory to STRATA_PLUGIN_PATH");
  describe(*type);
}

}  // namespace

void addPluginsCommand(CLI::App& app, int& exitCode) {
  auto typeName = std::make_shared<std::string>();
  auto reference = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand("plugins", "list the node types of the plugins found, or describe one");
  command->add_option("--describe", *typeName, "show one type's inputs and parameters, or the scene's settings")
      ->type_name("TYPE|scene");
  command->add_option("--reference", *reference, "write the parameter reference (Markdown) into a folder")
      ->type_name("DIR");
  command->callback([typeName, reference, &exitCode] {
    exitCode = reportingErrors([&] {
      PluginRegistry registry;
      registry.loadDirectories(defaultPluginDirectories());
      if (!reference->empty()) return writeReference(registry, *reference);
      if (typeName->empty()) return list(registry);
      describe(registry, *typeName);
    });
  });
}

}  // namespace strata::cli
