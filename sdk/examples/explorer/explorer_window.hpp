#pragma once
#include <string>
#include <vector>

struct GLFWwindow;

namespace explorer {

// The explorer's window: GLFW with an OpenGL 4.5 core context, made current on this thread, and Dear ImGui
// on it. Strata has no part in this; the engine is made afterwards, on the context this opens.
class ExplorerWindow {
 public:
  // Throws std::runtime_error saying what to do when no window or no OpenGL 4.5 context can be had.
  ExplorerWindow(int width, int height, const std::string& title);
  ~ExplorerWindow();
  ExplorerWindow(const ExplorerWindow&) = delete;
  ExplorerWindow& operator=(const ExplorerWindow&) = delete;

  bool open() const;  // until the user closes it
  // The framebuffer's size in pixels, after polling events (it changes as the window is resized).
  void beginFrame(int& width, int& height);
  void beginPanel();  // ImGui's new frame: the panel's calls follow
  void endPanel();    // draws the panel over what the framebuffer holds
  void endFrame();    // shows the frame
  // The back buffer as RGBA8 rows, top row first: the frame with the panel over it, as the user sees it.
  std::vector<unsigned char> readBack(int width, int height) const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace explorer
