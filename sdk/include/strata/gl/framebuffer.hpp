#pragma once
#include <strata/export.hpp>
#include <vector>

#include <strata/gl.hpp>
#include <strata/gl/texture.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// An off-screen render target: colour attachments of the given formats and an optional depth attachment,
// `samples` per pixel (multisampled textures where it is over 1).
class Framebuffer {
 public:
  Framebuffer() = default;
  Framebuffer(int width, int height, const std::vector<GLenum>& colorFormats, GLenum depthFormat = 0, int samples = 1);
  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  GLuint id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  const Texture& color(int index) const { return colors_.at(index); }
  const Texture& depth() const { return depth_; }
  // Binds for drawing and sets the viewport to the whole target.
  void bind() const;

 private:
  GLuint id_ = 0;
  int width_ = 0;
  int height_ = 0;
  int samples_ = 1;
  std::vector<Texture> colors_;
  Texture depth_;
};

// One triangle that covers the viewport, for screen passes; the vertex shader "strata/fullscreen.vert"
// places its corners. Make it on the GL thread with the context that draws it (vertex arrays are not
// shared between contexts).
class FullscreenTriangle {
 public:
  FullscreenTriangle();
  ~FullscreenTriangle();
  FullscreenTriangle(const FullscreenTriangle&) = delete;
  FullscreenTriangle& operator=(const FullscreenTriangle&) = delete;

  void draw() const;

 private:
  GLuint vertexArray_ = 0;  // empty: core profile needs one bound even when no attribute is read
};

}  // namespace strata
STRATA_EXPORTS_END
