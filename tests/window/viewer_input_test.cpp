// The viewer (issue 9) under Xvfb takes keyboard and mouse events sent to its window through the X server,
// as a user's hands would send them (XTest): a left drag orbits, the wheel zooms toward the pointer, the
// arrows orbit and + zooms, Home brings the pipeline's camera back; and the frame it shows is written as a screenshot
// that reads back the same.
#include <gtest/gtest.h>

#include <cmath>

#include <strata/host/engine.hpp>
#include <strata/viewer/viewer.hpp>

#include "shared_window.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

#include <GLFW/glfw3.h>
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>

namespace strata::test {
namespace {

const char* kGlobe =
    "strata: 1\ncamera: {lon: 20, lat: 10, altitude: 1.2e7}\nnodes:\n"
    "  colours: {type: source.procedural, kind: color}\n"
    "  globe: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: globe, surface: [colours]}\n";

class ViewerInput : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(display_, nullptr) << "no X display: the window tests run under xvfb-run";
    EngineOptions options;
    options.pluginDirectories = {STRATA_TEST_PLUGIN_DIR};
    engine_ = std::make_unique<Engine>(options);
    engine_->load(directory_.write("globe.yaml", kGlobe));
    viewer_ = std::make_unique<viewer::Viewer>(window_, *engine_);
    frames(2);
  }
  void TearDown() override {
    if (display_) XCloseDisplay(display_);
  }

  // Lets the window take what was sent, one frame each.
  void frames(int count) {
    for (int i = 0; i < count; ++i) {
      XSync(display_, 0);
      viewer_->frame();
    }
  }
  // The pointer to (x, y) of the window, away from the folded panels at its top left.
  void pointerTo(int x, int y) {
    int left = 0, top = 0;
    glfwGetWindowPos(window_.handle(), &left, &top);
    XTestFakeMotionEvent(display_, -1, left + x, top + y, 0);
    frames(1);
  }
  void button(unsigned number, bool pressed) {
    XTestFakeButtonEvent(display_, number, pressed ? 1 : 0, 0);
    frames(1);
  }
  void key(KeySym symbol) {
    const KeyCode code = XKeysymToKeycode(display_, symbol);
    XTestFakeKeyEvent(display_, code, 1, 0);
    XTestFakeKeyEvent(display_, code, 0, 0);
    frames(1);
  }

  GlfwWindow& window_ = sharedWindow();
  Display* display_ = XOpenDisplay(nullptr);  // the window's server, as another client: a user's hands
  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<viewer::Viewer> viewer_;
};

TEST_F(ViewerInput, ALeftDragOrbitsTheGlobe) {
  const Camera before = engine_->camera();
  pointerTo(200, 150);
  button(1, true);
  pointerTo(240, 150);
  button(1, false);
  EXPECT_LT(engine_->camera().lon, before.lon - 1.0) << "dragged east, the globe turns: the eye goes west";
  EXPECT_NEAR(engine_->camera().lat, before.lat, 1e-9);
}

TEST_F(ViewerInput, TheWheelAndPlusZoomAndTheArrowsOrbit) {
  const Camera before = engine_->camera();
  pointerTo(200, 150);
  button(4, true);  // the wheel, away from the user, with the pointer right of and below the middle
  button(4, false);
  EXPECT_NEAR(engine_->camera().altitude, before.altitude * 0.85, 1.0);
  EXPECT_GT(engine_->camera().lon, before.lon + 0.1) << "toward the ground under the pointer: east";
  EXPECT_LT(engine_->camera().lat, before.lat - 0.1) << "and south";
  key(XK_equal);
  EXPECT_NEAR(engine_->camera().altitude, before.altitude * 0.85 * 0.85, 1.0);
  key(XK_Up);
  EXPECT_GT(engine_->camera().lat, before.lat + 1.0);
  key(XK_Home);
  EXPECT_EQ(engine_->camera(), engine_->pipeline().camera);
}

// At any size, through the headless path, whatever the window's.
// W flies a tenth of the altitude along the line of sight: tilted 60 degrees toward the north, down by
// half of that and north by the rest; S flies back.
TEST_F(ViewerInput, WAndSFlyAlongTheLineOfSight) {
  engine_->camera().tilt = 60.0;
  const Camera before = engine_->camera();
  pointerTo(200, 150);
  key(XK_w);
  EXPECT_NEAR(engine_->camera().altitude, before.altitude * (1.0 - 0.1 * 0.5), 1.0);
  EXPECT_GT(engine_->camera().lat, before.lat + 1.0);
  key(XK_s);
  EXPECT_NEAR(engine_->camera().lat, before.lat, 0.5) << "back about where it was";
}

TEST_F(ViewerInput, WritesAScreenshotOfAnySize) {
  viewer_->screenshot(directory_.path() / "wide.png", 400, 100);
  const Image shot = readImage(directory_.path() / "wide.png");
  EXPECT_EQ(shot.width, 400);
  EXPECT_EQ(shot.height, 100);
  EXPECT_GT(shot.at(200, 50)[0] + shot.at(200, 50)[1] + shot.at(200, 50)[2], 0) << "the globe in its middle";
}

TEST_F(ViewerInput, WritesTheFrameItShowsAsAScreenshot) {
  const FrameOutput* frame = viewer_->frame();
  ASSERT_NE(frame, nullptr);
  frame->write(directory_.path() / "shot.png");
  const Image shot = readImage(directory_.path() / "shot.png");
  EXPECT_EQ(shot.rgba, readPixels(frame->frame()));
  int planet = 0;
  for (std::size_t i = 0; i < shot.rgba.size(); i += 4)
    planet += shot.rgba[i] + shot.rgba[i + 1] + shot.rgba[i + 2] > 0;
  EXPECT_GT(planet, 1000) << "the globe in the shot";
}

}  // namespace
}  // namespace strata::test
