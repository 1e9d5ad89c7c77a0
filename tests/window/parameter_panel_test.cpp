// The viewer's panels (issue 9) under Xvfb: generated from the plugins' parameter declarations, the
// parameter panel changes a parameter through its model (a live one in the next frame, nothing rebuilt);
// it and the scene panel draw over the frame in a real window; and an edited pipeline file is noticed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <strata/host/engine.hpp>
#include <strata/viewer/panel_overlay.hpp>
#include <strata/viewer/parameter_panel.hpp>
#include <strata/viewer/pipeline_watcher.hpp>
#include <strata/viewer/scene_panel.hpp>
#include <strata/window/glfw_window.hpp>

#include "shared_window.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

const char* kRelief =
    "strata: 1\ncamera: {lon: 20, lat: 10, altitude: 1.2e7}\nnodes:\n"
    "  heights: {type: source.procedural, kind: height}\n"
    "  shaded: {type: composite.relief, height: heights, exaggeration: 20, blend: alone}\n"
    "  globe: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: globe, surface: [shaded], shading: none}\n";

class ParameterPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    EngineOptions options;
    options.pluginDirectories = {STRATA_TEST_PLUGIN_DIR};
    engine_ = std::make_unique<Engine>(options);
    engine_->load(directory_.write("relief.yaml", kRelief));
  }

  viewer::ParameterControl control(const std::string& node, const std::string& name) {
    const auto controls = viewer::parameterControls(*engine_);
    const auto found = std::find_if(controls.begin(), controls.end(), [&](const viewer::ParameterControl& c) {
      return c.node == node && c.declaration->name == name;
    });
    EXPECT_NE(found, controls.end()) << node << "." << name;
    return *found;
  }

  std::vector<unsigned char> frame() { return readPixels(engine_->render(160, 120).frame()); }

  GlfwWindow& window_ = sharedWindow();  // first: the engine renders on its context
  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_;
};

TEST_F(ParameterPanelTest, EveryNodesParametersAreControlsFromTheirDeclarations) {
  const viewer::ParameterControl azimuth = control("shaded", "azimuth");
  EXPECT_EQ(std::get<double>(azimuth.value), 315.0);
  EXPECT_EQ(azimuth.declaration->units, "deg");
  EXPECT_TRUE(azimuth.declaration->live);
  EXPECT_EQ(std::get<std::string>(control("shaded", "blend").value), "alone");
  EXPECT_EQ(viewer::overrideOf(control("shaded", "blend"), std::string("multiply")), "nodes.shaded.blend=\"multiply\"");
}

TEST_F(ParameterPanelTest, ItsModelChangesALiveParameterForTheNextFrame) {
  const std::vector<unsigned char> before = frame();
  EXPECT_TRUE(viewer::apply(*engine_, control("shaded", "azimuth"), 135.0));
  EXPECT_EQ(std::get<double>(control("shaded", "azimuth").value), 135.0);
  EXPECT_NE(frame(), before);
  EXPECT_FALSE(viewer::apply(*engine_, control("heights", "scale"), 2.0)) << "not live: the pipeline loads again";
  EXPECT_EQ(std::get<double>(control("heights", "scale").value), 2.0);
}

TEST_F(ParameterPanelTest, TheScenesSettingsAreControlsToo) {
  const viewer::ParameterControl radius = control("body", "radius");
  EXPECT_EQ(std::get<double>(radius.value), 6371000.0) << "the body's default: the pipeline gives none";
  EXPECT_EQ(viewer::overrideOf(radius, 3389500.0), "body.radius=3389500");
  engine_->camera().lon = 25.0;  // the viewer moved
  const viewer::ParameterControl fov = control("camera", "fov");
  EXPECT_TRUE(viewer::apply(*engine_, fov, 30.0)) << "the camera's values move the view at once";
  EXPECT_EQ(engine_->camera().fov, 30.0);
  EXPECT_EQ(engine_->camera().lon, 25.0) << "and leave the rest of the view where the viewer put it";
  EXPECT_EQ(std::get<double>(control("camera", "lon").value), 25.0);
  EXPECT_FALSE(viewer::apply(*engine_, control("cache", "budget"), std::int64_t(64)));
  EXPECT_EQ(engine_->pipeline().cache.budgetBytes, std::uint64_t(64) << 20);
}

TEST(PipelineWatcher, SaysWhenTheFileWasEdited) {
  TemporaryDirectory directory;
  const auto file = directory.write("p.yaml", kRelief);
  viewer::PipelineWatcher watcher(std::vector<std::filesystem::path>{file});
  EXPECT_FALSE(watcher.changed());
  std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(1));
  EXPECT_TRUE(watcher.changed());
  EXPECT_FALSE(watcher.changed()) << "once";
  std::filesystem::remove(file);
  EXPECT_FALSE(watcher.changed()) << "a file being rewritten is looked at again later";
}

// A scene of several bodies is loaded again when one of its bodies' files is edited.
TEST(PipelineWatcher, WatchesTheBodiesFilesOfAScene) {
  TemporaryDirectory directory;
  Pipeline scene;
  scene.file = directory.write("scene.yaml", "strata: 1\n");
  scene.bodies.push_back({.id = "moon"});
  scene.bodies.back().pipeline.file = directory.write("moon.yaml", kRelief);
  viewer::PipelineWatcher watcher(scene);
  EXPECT_FALSE(watcher.changed());
  const auto moon = scene.bodies.back().pipeline.file;
  std::filesystem::last_write_time(moon, std::filesystem::last_write_time(moon) + std::chrono::seconds(1));
  EXPECT_TRUE(watcher.changed());
  EXPECT_FALSE(watcher.changed()) << "once";
}

TEST_F(ParameterPanelTest, DrawsOverTheFrameInTheWindow) {
  viewer::PanelOverlay overlay(window_);
  viewer::ParameterPanel panel;
  int width = 0, height = 0;
  window_.framebufferSize(width, height);
  const FrameOutput& output = engine_->render(width, height);
  std::vector<unsigned char> shown(std::size_t(width) * height * 4);
  for (int i = 0; i < 2; ++i) {  // ImGui lays a window out in its first frame and draws it from the second
    glBlitNamedFramebuffer(output.frame().id(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
    overlay.begin();
    panel.draw(*engine_);
    viewer::drawScenePanel(*engine_);
    overlay.end();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, shown.data());
    window_.swapBuffers();
  }
  std::vector<unsigned char> rendered = readPixels(output.frame());  // top row first; shown is bottom-up
  int differing = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      differing += shown[(std::size_t(height - 1 - y) * width + x) * 4] != rendered[(std::size_t(y) * width + x) * 4];
  EXPECT_GT(differing, 1000) << "the panel covers part of the frame";
  EXPECT_LT(differing, width * height) << "and leaves the rest";
}

}  // namespace
}  // namespace strata::test
