#pragma once
#include <functional>
#include <memory>
#include <string>

#include <strata/gl/context.hpp>

struct GLFWwindow;

namespace strata {

// The keys the viewer navigates by: the arrows, + and - (or Page Up and Page Down), W and S, Home.
enum class NavigationKey { Left, Right, Up, Down, Closer, Farther, Forward, Back, Home };

// What the window reports of the user's hands, in window pixels.
struct PointerInput {
  std::function<void(double dx, double dy, int button)> drag;    // button 0 left, 1 right, 2 middle
  std::function<void(double steps, double x, double y)> scroll;  // positive: away from the user; at the pointer
  std::function<void(NavigationKey key)> key;                    // pressed, or held and repeating
};

// An OpenGL 4.5 core context with a window, through GLFW. Throws std::runtime_error when no display or
// no 4.5 context is available, saying which.
class GlfwWindow : public GlContext {
 public:
  GlfwWindow(int width, int height, const std::string& title, bool debug = false);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  void makeCurrent() override;
  std::string description() const override;

  bool shouldClose() const;
  void pollEvents();
  void swapBuffers();
  void framebufferSize(int& width, int& height) const;
  void setPointerInput(PointerInput input);
  // The GLFW window, for toolkits that attach to it (the viewer's panel).
  GLFWwindow* handle() const { return window_; }

 private:
  static void onCursor(GLFWwindow* window, double x, double y);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  GLFWwindow* window_ = nullptr;
  PointerInput input_;
  double lastX_ = 0.0, lastY_ = 0.0;
  bool tracking_ = false;
};

}  // namespace strata
