// strata/gl/surface_buffer.hpp on the headless context: the layout each kind of shading normal makes (the bare
// sphere's 8 bytes a sample, the displaced surface's 16, a generator's own attachments after them), and what a
// frame starts from: no surface anywhere, depth at infinity.
#include <gtest/gtest.h>

#include <vector>

#include <strata/gl.hpp>
#include <strata/gl/surface_buffer.hpp>

#include "rendering.hpp"

namespace strata::test {
namespace {

GLint internalFormat(const Texture& texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format;
}

// The first texel of a single-sampled attachment, as RGBA floats (or its depth in [0]).
std::vector<float> firstTexel(const Texture& texture, GLenum format = GL_RGBA) {
  std::vector<float> texel(4, 7.0f);
  glGetTextureSubImage(texture.id(), 0, 0, 0, 0, 1, 1, 1, format, GL_FLOAT, GLsizei(texel.size() * sizeof(float)),
                       texel.data());
  return texel;
}

TEST(SurfaceBuffer, TheBareSphereStoresLongitudeAndLatitudeAlone) {
  headlessContext();
  SurfaceBuffer buffer(ShadingNormal::OfTheSphere);
  buffer.begin(16, 8, 1);
  EXPECT_EQ(internalFormat(buffer.framebuffer().color(0)), GL_RG32F);
  EXPECT_EQ(internalFormat(buffer.framebuffer().depth()), GL_DEPTH_COMPONENT32F);
  const std::vector<float> cleared = firstTexel(buffer.framebuffer().color(0));
  EXPECT_EQ(cleared[0], SurfaceBuffer::kNoSurface) << "no surface anywhere";
  EXPECT_EQ(cleared[1], 0.0f);
  buffer.end();
}

TEST(SurfaceBuffer, ADisplacedSurfaceStoresItsNormalAndAGeneratorsOwnAttachmentsFollow) {
  headlessContext();
  SurfaceBuffer buffer(ShadingNormal::Stored, {{GL_R32F, {5.0f, 0, 0, 0}}});
  buffer.begin(16, 8, 1);
  EXPECT_EQ(internalFormat(buffer.framebuffer().color(0)), GL_RGBA32F);
  EXPECT_EQ(internalFormat(buffer.framebuffer().color(1)), GL_R32F);
  EXPECT_EQ(firstTexel(buffer.framebuffer().color(0)), (std::vector<float>{SurfaceBuffer::kNoSurface, 0, 0, 0}));
  EXPECT_EQ(firstTexel(buffer.framebuffer().color(1))[0], 5.0f) << "its own clear value";
  EXPECT_EQ(firstTexel(buffer.framebuffer().depth(), GL_DEPTH_COMPONENT)[0], 0.0f)
      << "reversed depth: 0 is infinitely far";
  buffer.end();
}

TEST(SurfaceBuffer, MultisampledBuffersKeepTheLayout) {
  headlessContext();
  for (const ShadingNormal normal : {ShadingNormal::OfTheSphere, ShadingNormal::Stored}) {
    SurfaceBuffer buffer(normal);
    buffer.begin(16, 8, 4);
    EXPECT_EQ(buffer.framebuffer().samples(), 4);
    EXPECT_EQ(internalFormat(buffer.framebuffer().color(0)), normal == ShadingNormal::Stored ? GL_RGBA32F : GL_RG32F);
    buffer.end();
  }
}

TEST(SurfaceBuffer, DrawingIntoItTakesTheReversedDepthTest) {
  headlessContext();
  SurfaceBuffer buffer(ShadingNormal::OfTheSphere);
  glDepthFunc(GL_LESS);
  buffer.begin(16, 8, 1);
  GLint function = 0;
  glGetIntegerv(GL_DEPTH_FUNC, &function);
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_EQ(function, GL_GREATER) << "nearer is larger";
  buffer.end();
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
}

}  // namespace
}  // namespace strata::test
