#include <cmath>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/raster_layer.hpp>

namespace strata {
namespace {

// The next mip level: each texel the mean of the (up to) 2x2 texels it covers. Texels carry coverage
// (premultiplied), so the mean of values and of coverage stays consistent where nodata is mixed in.
RasterImage halved(const RasterImage& image) {
  RasterImage out{std::max(1, image.width / 2), std::max(1, image.height / 2), image.channels, {}};
  out.texels.assign(std::size_t(out.width) * out.height * image.channels, 0.0f);
  const int spanX = image.width > 1 ? 2 : 1, spanY = image.height > 1 ? 2 : 1;
  const float share = 1.0f / float(spanX * spanY);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int dy = 0; dy < spanY; ++dy)
        for (int dx = 0; dx < spanX; ++dx)
          for (int c = 0; c < image.channels; ++c)
            out.texels[(std::size_t(y) * out.width + x) * image.channels + c] +=
                share * image.texels[(std::size_t(y * spanY + dy) * image.width + x * spanX + dx) * image.channels + c];
  return out;
}

}  // namespace

RasterLayer::RasterLayer(std::string nodeId, LayerKind kind) : ProjectedRasterLayer(std::move(nodeId), kind) {}

void RasterLayer::upload(const RasterImage& image, RasterGeoreference georeference) {
  place(std::move(georeference), image.width, image.height);
  const bool colour = image.channels == 4;
  texture_ = Texture(colour ? GL_RGBA16F : GL_RG32F, image.width, image.height, mipLevels(image.width, image.height));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // The mip chain is averaged here rather than by glGenerateTextureMipmap: Mesa's llvmpipe was seen to
  // leave non-finite texels in the float levels it generated, which tore holes in displaced geometry.
  int level = 0;
  for (RasterImage mip = image;; mip = halved(mip), ++level) {
    glTextureSubImage2D(texture_.id(), level, 0, 0, mip.width, mip.height, colour ? GL_RGBA : GL_RG, GL_FLOAT,
                        mip.texels.data());
    if (mip.width == 1 && mip.height == 1) break;
  }
  // A raster that goes all the way round wraps across its east/west seam when filtered.
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, repeatX() ? GL_REPEAT : GL_CLAMP_TO_EDGE);
}

std::string RasterLayer::glsl() const {
  return samplingGlsl("uniform sampler2D " + prefix() + "_texture;\n",
                      "sampleFootprint(" + prefix() + "_texture, uv, stepX, stepY, repeatX)");
}

void RasterLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  units.bind(program, prefix() + "_texture", texture_.id());
  bindSampling(program);
}

}  // namespace strata
