#include <strata/viewer/viewer.hpp>

#include <array>

#include <strata/error.hpp>
#include <strata/gl.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/log.hpp>
#include <strata/viewer/orbit_controls.hpp>
#include <strata/viewer/scene_panel.hpp>

namespace strata::viewer {

Viewer::Viewer(GlfwWindow& window, Engine& engine)
    : window_(window), engine_(engine), overlay_(window), watcher_(engine.pipeline()) {
  navigate();
}

// The controls are made per event: a change in the panel may load the pipeline again, and with it the body.
void Viewer::navigate() {
  const auto controls = [this] { return OrbitControls(engine_.cameraBody(), engine_.camera()); };
  window_.setPointerInput({[this, controls](double dx, double dy, int button) {
                             if (!overlay_.wantsPointer()) controls().drag(dx, dy, button, height_);
                           },
                           [this, controls](double steps, double x, double y) {
                             if (!overlay_.wantsPointer()) controls().scrollToward(steps, x, y, width_, height_);
                           },
                           [this, controls](NavigationKey key) {
                             if (key == NavigationKey::Home)
                               engine_.camera() = engine_.pipeline().camera;
                             else
                               controls().key(key, height_);
                           }});
}

// The pipeline's file was edited: load it again, keeping the camera; a file that no longer loads leaves the
// pipeline as it was, and says why in the panel and in the log (strata/log.hpp).
void Viewer::reload() {
  try {
    engine_.reload();
    watcher_ = PipelineWatcher(engine_.pipeline());  // a scene's bodies may be other files now
    failed_ = false;
    panel_.report({});
  } catch (const Error& error) {
    logMessage({LogLevel::Error, error.what()});
    panel_.report(error.what());
  }
}

// A node that throws while rendering (a plugin's fault, a file gone) would throw again next frame: the
// viewer shows the panels over a blank frame, with the error, until the file is edited.
const FrameOutput* Viewer::renderedFrame() {
  if (failed_) return nullptr;
  try {
    return &engine_.render(width_, height_);
  } catch (const Error& error) {
    logMessage({LogLevel::Error, error.what()});
    panel_.report(error.what());
    failed_ = true;
    return nullptr;
  }
}

const FrameOutput* Viewer::frame() {
  window_.pollEvents();
  if (watcher_.changed()) reload();
  window_.framebufferSize(width_, height_);
  if (width_ < 1 || height_ < 1) return nullptr;  // minimised
  const FrameOutput* frame = renderedFrame();
  if (frame)
    glBlitNamedFramebuffer(frame->frame().id(), 0, 0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
  else
    glClearNamedFramebufferfv(0, GL_COLOR, 0, std::array<GLfloat, 4>{0.0f, 0.0f, 0.0f, 1.0f}.data());
  overlay_.begin();
  panel_.draw(engine_);
  drawScenePanel(engine_);
  overlay_.end();
  window_.swapBuffers();
  return frame;
}

void Viewer::screenshot(const std::filesystem::path& file, int width, int height) {
  engine_.renderSettled(width, height).write(file);
}

}  // namespace strata::viewer
