#pragma once
#include <array>

#include <strata/gl.hpp>

namespace strata {

// The host's OpenGL state that a frame of the engine changes and a host drawing after it relies on: the
// framebuffers bound for drawing and reading, the viewport and the clip control (the engine draws with
// reversed depth in [0, 1]). Saved when made, put back when destroyed, also when a node throws mid-frame,
// so that a host's UI drawn after Engine::render lands in the host's framebuffer (docs/sdk/embedding.md).
class HostGlState {
 public:
  HostGlState();
  ~HostGlState();
  HostGlState(const HostGlState&) = delete;
  HostGlState& operator=(const HostGlState&) = delete;

 private:
  GLint drawFramebuffer_ = 0;
  GLint readFramebuffer_ = 0;
  std::array<GLint, 4> viewport_{};
  GLint clipOrigin_ = GL_LOWER_LEFT;
  GLint clipDepth_ = GL_NEGATIVE_ONE_TO_ONE;
};

}  // namespace strata
