#include <GLFW/glfw3.h>

#include <optional>
#include <stdexcept>

#include <strata/window/glfw_window.hpp>

namespace strata {
namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

std::optional<NavigationKey> navigationKeyOf(int key) {
  switch (key) {
    case GLFW_KEY_LEFT: return NavigationKey::Left;
    case GLFW_KEY_RIGHT: return NavigationKey::Right;
    case GLFW_KEY_UP: return NavigationKey::Up;
    case GLFW_KEY_DOWN: return NavigationKey::Down;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
    case GLFW_KEY_PAGE_UP: return NavigationKey::Closer;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
    case GLFW_KEY_PAGE_DOWN: return NavigationKey::Farther;
    case GLFW_KEY_W: return NavigationKey::Forward;
    case GLFW_KEY_S: return NavigationKey::Back;
    case GLFW_KEY_HOME: return NavigationKey::Home;
    default: return std::nullopt;
  }
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool debug) {
  if (!glfwInit())
    throw std::runtime_error("cannot open a window: " + lastGlfwError() +
                             "\n  fix: run under a desktop session or Xvfb, or use `strata render` (headless)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    std::string reason = lastGlfwError();
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 4.5 core window: " + reason);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetCursorPosCallback(window_, onCursor);
  glfwSetScrollCallback(window_, onScroll);
  glfwSetKeyCallback(window_, onKey);
  makeCurrent();
  glfwSwapInterval(1);
  keepLoadedLibrariesResident();
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::makeCurrent() { glfwMakeContextCurrent(window_); }

std::string GlfwWindow::description() const { return "GLFW window"; }

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

void GlfwWindow::pollEvents() { glfwPollEvents(); }

void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }

void GlfwWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

void GlfwWindow::setPointerInput(PointerInput input) { input_ = std::move(input); }

void GlfwWindow::onCursor(GLFWwindow* window, double x, double y) {
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  int button = -1;
  for (int b : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE})
    if (glfwGetMouseButton(window, b) == GLFW_PRESS) button = b;
  if (button >= 0 && self->tracking_ && self->input_.drag)
    self->input_.drag(x - self->lastX_, y - self->lastY_, button);
  self->tracking_ = true;
  self->lastX_ = x;
  self->lastY_ = y;
}

void GlfwWindow::onScroll(GLFWwindow* window, double, double dy) {
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  if (!self->input_.scroll) return;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  self->input_.scroll(dy, x, y);
}

void GlfwWindow::onKey(GLFWwindow* window, int key, int, int action, int) {
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  if (action == GLFW_RELEASE || !self->input_.key) return;
  const std::optional<NavigationKey> navigation = navigationKeyOf(key);
  if (navigation) self->input_.key(*navigation);
}

}  // namespace strata
