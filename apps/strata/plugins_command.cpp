#include <cstdio>
#include <memory>

#include <strata/node_type.hpp>
#include <strata/plugin_registry.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

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
  std::printf("\n`strata plugins --describe TYPE` shows a type's inputs and parameters.\n");
}

std::string range(const ParameterDeclaration& p) {
  if (!p.choices.empty()) {
    std::string all;
    for (const auto& choice : p.choices) all += (all.empty() ? "" : "|") + choice;
    return all;
  }
  if (!p.minimum && !p.maximum) return "";
  return "[" + (p.minimum ? formatValue(*p.minimum) : std::string("-inf")) + ", " +
         (p.maximum ? formatValue(*p.maximum) : std::string("inf")) + "]";
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
  if (type.parameters.empty()) std::printf("  (none)\n");
  for (const ParameterDeclaration& p : type.parameters) {
    std::string value = p.defaultValue ? "default " + formatValue(*p.defaultValue)
                        : p.optional   ? "optional"
                                       : "required";
    std::printf("  %-16s %-9s %-14s %-16s %-4s %s%s\n", p.name.c_str(), toString(p.type), value.c_str(),
                range(p).c_str(), p.units.c_str(), p.live ? "(live) " : "", p.doc.c_str());
  }
  std::printf("\n(live): changes take effect in the next frame with nothing rebuilt (Engine::set, the viewer)\n");
}

}  // namespace

void addPluginsCommand(CLI::App& app, int& exitCode) {
  auto typeName = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand("plugins", "list the node types of the plugins found, or describe one");
  command->add_option("--describe", *typeName, "show one type's inputs and parameters")->type_name("TYPE");
  command->callback([typeName, &exitCode] {
    exitCode = reportingErrors([&] {
      PluginRegistry registry;
      registry.loadDirectories(defaultPluginDirectories());
      if (typeName->empty()) return list(registry);
      const NodeTypeDeclaration* type = registry.find(*typeName);
      if (!type)
        throw Error({"strata plugins"}, "no node type '" + *typeName + "' is registered",
                    "run `strata plugins` to list the types, or add a plugin directory to STRATA_PLUGIN_PATH");
      describe(*type);
    });
  });
}

}  // namespace strata::cli
