#include <stdexcept>
#include <string>
#include <utility>

#include <strata/gl/framebuffer.hpp>

namespace strata {

Framebuffer::Framebuffer(int width, int height, const std::vector<GLenum>& colorFormats, GLenum depthFormat,
                         int samples)
    : width_(width), height_(height), samples_(samples) {
  glCreateFramebuffers(1, &id_);
  std::vector<GLenum> drawBuffers;
  for (GLenum format : colorFormats) {
    colors_.push_back(Texture::multisampled(format, width, height, samples));
    auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + drawBuffers.size());
    glNamedFramebufferTexture(id_, attachment, colors_.back().id(), 0);
    drawBuffers.push_back(attachment);
  }
  glNamedFramebufferDrawBuffers(id_, static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
  if (depthFormat) {
    depth_ = Texture::multisampled(depthFormat, width, height, samples);
    glNamedFramebufferTexture(id_, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  }
  GLenum status = glCheckNamedFramebufferStatus(id_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                             " is incomplete (status 0x" + std::to_string(status) + ")");
}

Framebuffer::~Framebuffer() {
  if (id_) glDeleteFramebuffers(1, &id_);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      width_(other.width_),
      height_(other.height_),
      samples_(other.samples_),
      colors_(std::move(other.colors_)),
      depth_(std::move(other.depth_)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  std::swap(samples_, other.samples_);
  std::swap(colors_, other.colors_);
  std::swap(depth_, other.depth_);
  return *this;
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glViewport(0, 0, width_, height_);
}

FullscreenTriangle::FullscreenTriangle() { glCreateVertexArrays(1, &vertexArray_); }

FullscreenTriangle::~FullscreenTriangle() { glDeleteVertexArrays(1, &vertexArray_); }

void FullscreenTriangle::draw() const {
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace strata
