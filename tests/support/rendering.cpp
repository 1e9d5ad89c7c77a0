#include "rendering.hpp"

#include <strata/plugin/plugin_registry.hpp>

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

const ShaderLibrary& pluginShaderLibrary() {
  static const ShaderLibrary library = [] {
    PluginRegistry plugins;
    plugins.loadDirectories({STRATA_TEST_PLUGIN_DIR});
    ShaderLibrary made;
    made.addPluginSources(plugins);
    return made;
  }();
  return library;
}

Image renderFrame(Engine& engine, const std::filesystem::path& pipelineFile, int width, int height) {
  engine.load(pipelineFile);
  const FrameOutput& output = engine.renderComplete(width, height);
  return Image{width, height, readPixels(output.frame())};
}

Image renderFrames(Engine& engine, const Camera& camera, int width, int height, int frames) {
  engine.camera() = camera;
  const FrameOutput* output = &engine.renderComplete(width, height);
  for (int frame = 1; frame < frames; ++frame) output = &engine.render(width, height);
  return Image{width, height, readPixels(output->frame())};
}

bool covered(const Image& image, int x, int y) {
  const std::array<int, 4> pixel = image.at(x, y);
  return pixel[0] + pixel[1] + pixel[2] > 0;
}

}  // namespace strata::test
