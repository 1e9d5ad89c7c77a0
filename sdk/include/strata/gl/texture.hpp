#pragma once
#include <strata/export.hpp>
#include <strata/gl.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Owns one GL texture name (GL_TEXTURE_2D, immutable storage).
class Texture {
 public:
  Texture() = default;
  Texture(GLenum internalFormat, int width, int height, int levels = 1);
  ~Texture();
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  GLuint id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
  int width_ = 0;
  int height_ = 0;
};

// Levels of a full mip chain for a width x height image.
int mipLevels(int width, int height);

}  // namespace strata
STRATA_EXPORTS_END
