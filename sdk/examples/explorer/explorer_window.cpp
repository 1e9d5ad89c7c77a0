#include "explorer_window.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include <strata/gl.hpp>  // epoxy: Strata's GL loader, which the explorer's own GL calls use too

#define GLFW_INCLUDE_NONE  // epoxy declares OpenGL; GLFW must not include GL/gl.h as well
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace explorer {
namespace {

std::string glfwProblem() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

}  // namespace

ExplorerWindow::ExplorerWindow(int width, int height, const std::string& title) {
  if (!glfwInit())
    throw std::runtime_error("cannot open a window: " + glfwProblem() +
                             "\n  fix: run it in a desktop session, or under Xvfb (xvfb-run -a mars-explorer ...)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);  // Strata needs OpenGL 4.5, core profile
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string problem = glfwProblem();
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 4.5 core window: " + problem);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);  // follow the display: no frames drawn that no one sees
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // leave no imgui.ini in the user's directory
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

ExplorerWindow::~ExplorerWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool ExplorerWindow::open() const { return !glfwWindowShouldClose(window_); }

void ExplorerWindow::beginFrame(int& width, int& height) {
  glfwPollEvents();
  glfwGetFramebufferSize(window_, &width, &height);
}

void ExplorerWindow::beginPanel() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ExplorerWindow::endPanel() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ExplorerWindow::endFrame() { glfwSwapBuffers(window_); }

std::vector<unsigned char> ExplorerWindow::readBack(int width, int height) const {
  const auto rowBytes = static_cast<std::size_t>(width) * 4;
  std::vector<unsigned char> bottomUp(rowBytes * static_cast<std::size_t>(height));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  std::vector<unsigned char> topDown(bottomUp.size());
  for (std::size_t row = 0; row < static_cast<std::size_t>(height); ++row)
    std::copy_n(&bottomUp[row * rowBytes], rowBytes, &topDown[(static_cast<std::size_t>(height) - 1 - row) * rowBytes]);
  return topDown;
}

}  // namespace explorer
