#include <algorithm>
#include <bit>
#include <utility>

#include <strata/gl/texture.hpp>

namespace strata {

Texture::Texture(GLenum internalFormat, int width, int height, int levels) : width_(width), height_(height) {
  glCreateTextures(GL_TEXTURE_2D, 1, &id_);
  glTextureStorage2D(id_, levels, internalFormat, width, height);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Texture Texture::multisampled(GLenum internalFormat, int width, int height, int samples) {
  if (samples <= 1) return Texture(internalFormat, width, height);
  Texture texture;
  texture.width_ = width;
  texture.height_ = height;
  texture.samples_ = samples;
  glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &texture.id_);
  // Fixed sample locations: every texel's samples sit alike, so a sample index means the same spot anywhere.
  glTextureStorage2DMultisample(texture.id_, samples, internalFormat, width, height, GL_TRUE);
  return texture;
}

Texture::~Texture() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_), samples_(other.samples_) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  std::swap(samples_, other.samples_);
  return *this;
}

int mipLevels(int width, int height) { return std::bit_width(static_cast<unsigned>(std::max(width, height))); }

const char* glslSamplerFor(int samples) { return samples > 1 ? "sampler2DMS" : "sampler2D"; }

}  // namespace strata
