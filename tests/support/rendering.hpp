#pragma once
#include <filesystem>
#include <memory>
#include <string>

#include <strata/gl/context.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/host/engine.hpp>

#include "test_rasters.hpp"

namespace strata::test {

// One headless context for the whole test program (contexts are costly to make on llvmpipe), with the
// engine loading the plugins of this build.
GlContext& headlessContext();
std::unique_ptr<Engine> makeEngine();

// The SDK's GLSL and every plugin's of this build, as an engine holds them: for tests that compile one of
// a plugin's shaders on its own.
const ShaderLibrary& pluginShaderLibrary();

// Loads `pipelineFile`, renders one frame and reads it back (top row first).
Image renderFrame(Engine& engine, const std::filesystem::path& pipelineFile, int width, int height);

// Renders the pipeline loaded in `engine` from `camera` for `frames` frames (the first until its pages have
// loaded: renderComplete) and reads back the last.
Image renderFrames(Engine& engine, const Camera& camera, int width, int height, int frames);

// Whether a pixel of an output.image frame shows the body: its background is black.
bool covered(const Image& image, int x, int y);

}  // namespace strata::test
