// A plugin module that claims a plugin ABI version this Strata does not have, for plugin_loading_test.
#include <strata/plugin/plugin.hpp>

namespace {
void registerNothing(strata::PluginRegistrar*) {}
}  // namespace

extern "C" __attribute__((visibility("default"))) const StrataPluginInfo* strata_plugin_entry() {
  static const StrataPluginInfo info{strata::kPluginAbiVersion + 1, "from-the-future", "9.9.9", registerNothing};
  return &info;
}
