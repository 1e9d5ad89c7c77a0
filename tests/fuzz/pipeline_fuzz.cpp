// Fuzz target: bytes as pipeline text, parsed against the built-in plugins' declarations. Lines after a
// line "#--set" are --set overrides, one a line. Bad input must end in a strata::Error.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace {

const strata::PluginRegistry& builtInPlugins() {
  static const strata::PluginRegistry registry = [] {
    strata::PluginRegistry plugins;
    plugins.loadDirectories(strata::defaultPluginDirectories());  // those beside the program first
    return plugins;
  }();
  return registry;
}

struct FuzzedPipeline {
  std::string text;
  std::vector<std::string> overrides;
};

FuzzedPipeline split(std::string_view input) {
  constexpr std::string_view kMarker = "\n#--set\n";
  const std::size_t marker = input.find(kMarker);
  if (marker == std::string_view::npos) return {std::string(input), {}};
  FuzzedPipeline pipeline{std::string(input.substr(0, marker + 1)), {}};
  std::string_view rest = input.substr(marker + kMarker.size());
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    pipeline.overrides.emplace_back(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  }
  return pipeline;
}

}  // namespace

// Before libFuzzer lists the instrumented modules, so that it counts the plugins' coverage too.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  builtInPlugins();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const FuzzedPipeline input = split({reinterpret_cast<const char*>(data), size});
  try {
    // In pipelines/, so that the sample pipelines' relative paths name files that exist.
    strata::parsePipeline(input.text, STRATA_FUZZ_PIPELINE_FILE, input.overrides, builtInPlugins());
  } catch (const strata::Error&) {
  }
  return 0;
}
