#pragma once
#include <strata/window/glfw_window.hpp>

namespace strata::test {

// One window for the whole test program: each GlfwWindow initialises and terminates GLFW, so two would not
// live at once, and opening the display once spares the X server a connection per test.
inline GlfwWindow& sharedWindow() {
  static GlfwWindow window(320, 240, "strata window tests");
  window.makeCurrent();
  return window;
}

}  // namespace strata::test
