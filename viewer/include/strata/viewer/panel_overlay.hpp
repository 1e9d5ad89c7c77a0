#pragma once
#include <strata/window/glfw_window.hpp>

namespace strata::viewer {

// Dear ImGui on a GlfwWindow (Debian's libimgui-dev: its GLFW and OpenGL 3 back ends), drawn over the frame
// the window shows. One per window, on its GL thread; ImGui chains the window's own input callbacks.
class PanelOverlay {
 public:
  explicit PanelOverlay(GlfwWindow& window);
  ~PanelOverlay();
  PanelOverlay(const PanelOverlay&) = delete;
  PanelOverlay& operator=(const PanelOverlay&) = delete;

  // Between them, ImGui calls build the panels of this frame; end() draws them into the window.
  void begin();
  void end();
  // Whether the pointer is over a panel, whose drags and scrolls are not the camera's.
  bool wantsPointer() const;
};

}  // namespace strata::viewer
