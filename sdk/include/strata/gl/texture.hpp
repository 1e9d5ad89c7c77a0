#pragma once
#include <strata/export.hpp>
#include <strata/gl.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Owns one GL texture name (GL_TEXTURE_2D, or GL_TEXTURE_2D_MULTISAMPLE with `samples` > 1; immutable
// storage).
class Texture {
 public:
  Texture() = default;
  Texture(GLenum internalFormat, int width, int height, int levels = 1);
  // A multisampled render target of `samples` per texel at the standard sample positions (read in GLSL
  // through a sampler2DMS); 1: a plain texture of one level.
  static Texture multisampled(GLenum internalFormat, int width, int height, int samples);
  ~Texture();
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  GLuint id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
  int width_ = 0;
  int height_ = 0;
  int samples_ = 1;
};

// Levels of a full mip chain for a width x height image.
int mipLevels(int width, int height);

// The GLSL sampler type that reads a texture of `samples` per texel (Texture::multisampled): "sampler2DMS" where
// it is over 1, texelFetch's last argument then the sample; else "sampler2D".
const char* glslSamplerFor(int samples);

}  // namespace strata
STRATA_EXPORTS_END
