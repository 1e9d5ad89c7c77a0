#include <strata/gl/surface_buffer.hpp>

#include <utility>

namespace strata {
namespace {

constexpr int kSharedAttachments = 1;  // the surface sample (strata/surface_buffer.glsl)

}  // namespace

SurfaceBuffer::SurfaceBuffer(ShadingNormal normal, std::vector<Attachment> extra)
    : normal_(normal), extra_(std::move(extra)) {}

void SurfaceBuffer::begin(int width, int height, int samples) {
  if (framebuffer_.width() != width || framebuffer_.height() != height || framebuffer_.samples() != samples ||
      framebuffer_.id() == 0) {
    std::vector<GLenum> formats{GLenum(normal_ == ShadingNormal::Stored ? GL_RGBA32F : GL_RG32F)};
    for (const Attachment& attachment : extra_) formats.push_back(attachment.format);
    framebuffer_ = Framebuffer(width, height, formats, GL_DEPTH_COMPONENT32F, samples);
  }
  framebuffer_.bind();
  const float noSurface[4] = {kNoSurface, 0, 0, 0}, farDepth = 0.0f;  // reversed depth: 0 is infinitely far
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, noSurface);
  for (std::size_t i = 0; i < extra_.size(); ++i)
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, GLint(kSharedAttachments + i), extra_[i].clear.data());
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
}

void SurfaceBuffer::end() const { glDisable(GL_DEPTH_TEST); }

}  // namespace strata
