// A frame shown in a real window is the frame the engine rendered: the pixels read back from the window's
// back buffer equal those of the output's framebuffer.
#include <gtest/gtest.h>

#include <strata/host/engine.hpp>
#include <strata/window/glfw_window.hpp>

#include "shared_window.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

TEST(Window, ShowsTheRenderedFrame) {
  TemporaryDirectory directory;
  writeCheckerboard(directory.path() / "cells.tif");
  auto pipeline = directory.write("globe.yaml",
                                  "strata: 1\ncamera: {lon: 20, lat: 10, altitude: 1.2e7}\nnodes:\n"
                                  "  cells: {type: source.gdal, path: " +
                                      (directory.path() / "cells.tif").string() +
                                      "}\n  globe: {type: geometry.icosahedral}\n"
                                      "  frame: {type: output.image, geometry: globe, surface: [cells]}\n");
  GlfwWindow& window = sharedWindow();
  int width = 0, height = 0;
  window.framebufferSize(width, height);
  ASSERT_GT(width, 0);
  EngineOptions options;
  options.pluginDirectories = {STRATA_TEST_PLUGIN_DIR};
  Engine engine(options);
  engine.load(pipeline);
  const FrameOutput& frame = engine.render(width, height);
  glBlitNamedFramebuffer(frame.frame().id(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);

  std::vector<unsigned char> shown(static_cast<std::size_t>(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, shown.data());
  std::vector<unsigned char> rendered = readPixels(frame.frame());  // top row first; shown is bottom-up
  const auto at = [&](const std::vector<unsigned char>& pixels, int x, int row) {
    return pixels[(row * width + x) * 4];
  };
  int planet = 0;
  for (int y = 0; y < height; y += 7)
    for (int x = 0; x < width; x += 7) {
      EXPECT_EQ(at(shown, x, height - 1 - y), at(rendered, x, y)) << x << "," << y;
      planet += at(rendered, x, y) > 0;
    }
  EXPECT_GT(planet, 100) << "the globe should fill much of the window";
  window.swapBuffers();
}

}  // namespace
}  // namespace strata::test
