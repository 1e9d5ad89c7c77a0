#pragma once
#include <strata/export.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/projection.hpp>
#include <strata/version.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Receives the node types and projections a plugin provides.
class PluginRegistrar {
 public:
  virtual ~PluginRegistrar() = default;
  virtual void add(NodeTypeDeclaration declaration) = 0;
  virtual void addProjection(ProjectionDeclaration declaration) = 0;
};

}  // namespace strata
STRATA_EXPORTS_END

// The one C entry point of a plugin module. The core reads abiVersion before it touches anything else,
// so a plugin built against another SDK is refused cleanly instead of crashing.
extern "C" {
struct StrataPluginInfo {
  int abiVersion;       // strata::kPluginAbiVersion the plugin was built with
  const char* name;     // e.g. "source-gdal"
  const char* version;  // the plugin's own version
  void (*registerTypes)(strata::PluginRegistrar* registrar);
};
}

#define STRATA_PLUGIN_ENTRY_SYMBOL "strata_plugin_entry"

// Defines the entry point: STRATA_PLUGIN("source-gdal", "1.0.0", registerFunction)
#define STRATA_PLUGIN(name, version, registerFunction)                                              \
  extern "C" __attribute__((visibility("default"))) const StrataPluginInfo* strata_plugin_entry() { \
    static const StrataPluginInfo info{strata::kPluginAbiVersion, name, version,                    \
                                       [](strata::PluginRegistrar* r) { registerFunction(*r); }};   \
    return &info;                                                                                   \
  }
