#include "host_gl_state.hpp"

namespace strata {

HostGlState::HostGlState() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth_);
}

HostGlState::~HostGlState() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepth_));
}

}  // namespace strata
