#include "rendering.hpp"

namespace strata::test {

GlContext& headlessContext() {
  static std::unique_ptr<GlContext> context = [] {
    auto made = createHeadlessContext(true);
    enableGlDebugOutput(false);
    return made;
  }();
  context->makeCurrent();
  return *context;
}

std::unique_ptr<Engine> makeEngine() {
  headlessContext();
  EngineOptions options;
  options.pluginDirectories = {STRATA_TEST_PLUGIN_DIR};
  return std::make_unique<Engine>(options);
}

Image renderFrame(Engine& engine, const std::filesystem::path& pipelineFile, int width, int height) {
  engine.load(pipelineFile);
  const FrameOutput& output = engine.renderComplete(width, height);
  return Image{width, height, readPixels(output.frame())};
}

}  // namespace strata::test
