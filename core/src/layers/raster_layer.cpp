#include <cmath>
#include <string_view>

#include <strata/gl/shader_program.hpp>
#include <strata/raster_layer.hpp>

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

// Whether the current context filters anisotropically without artefacts. Mesa's llvmpipe (22.3) returned
// near-white texels for scattered 2x2 pixel quads with it on; isotropic filtering there is only blurrier.
bool anisotropicFilteringWorks() {
  const bool offered = epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic");
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return offered && !(renderer && std::string_view(renderer).starts_with("llvmpipe"));
}

// Whether a raster `width` texels wide spans one period of a periodic projection.
bool spansPeriod(const RasterGeoreference& georeference, int width) {
  const std::optional<double> period = georeference.projection->periodX();
  return period && std::abs(std::abs(georeference.geotransform[1]) * width - *period) <= 1e-9 * *period;
}

// Texture coordinates per GLSL map unit: u = x * s.x + s.y, v = y * s.z + s.w (see Projection::glslMapScale).
glm::vec4 mapToTexture(const RasterGeoreference& georeference, int width, int height) {
  const std::array<double, 6>& t = georeference.geotransform;
  const double scale = georeference.projection->glslMapScale();
  const double uSpan = t[1] * width, vSpan = t[5] * height;
  return glm::vec4(glm::dvec4(scale / uSpan, -t[0] / uSpan, scale / vSpan, -t[3] / vSpan));
}

}  // namespace

RasterLayer::RasterLayer(std::string nodeId, LayerKind kind) : prefix_("layer_" + glslIdentifier(nodeId)), kind_(kind) {}

void RasterLayer::setValueTransform(double scale, double offset) {
  scale_ = scale;
  offset_ = offset;
}

void RasterLayer::upload(const RasterImage& image, RasterGeoreference georeference) {
  georeference_ = std::move(georeference);
  const std::array<glm::dvec4, 2> projection = georeference_.projection->glslParameters();
  uniforms_ = {{glm::vec4(projection[0]), glm::vec4(projection[1])},
               mapToTexture(georeference_, image.width, image.height),
               spansPeriod(georeference_, image.width)};
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
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, uniforms_.repeatX ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  // Texels stretch where a projection is stretched (toward the poles of equirectangular maps);
  // anisotropic filtering keeps them sharp there.
  if (anisotropicFilteringWorks()) glTextureParameterf(texture_.id(), GL_TEXTURE_MAX_ANISOTROPY, 8.0f);
}

std::string RasterLayer::samplingFunction() const { return prefix_; }

std::string RasterLayer::glsl() const {
  const std::string& p = prefix_;
  const Projection& projection = *georeference_.projection;
  const bool colour = kind_ == LayerKind::Color || kind_ == LayerKind::Chroma || kind_ == LayerKind::Normal;
  std::string value = colour ? "vec4(t.rgb / t.a, t.a)"
                             : "vec4(t.r / t.g * " + p + "_scaleOffset.x + " + p + "_scaleOffset.y, 0.0, 0.0, t.g)";
  return "#include \"strata/projected_raster.glsl\"\n"
         "#include \"" + projection.glslInclude() + "\"\n"
         "uniform sampler2D " + p + "_texture;\n"
         "uniform vec4 " + p + "_projectionA;\n"
         "uniform vec4 " + p + "_projectionB;\n"
         "uniform vec4 " + p + "_mapToTexture;\n"
         "uniform vec2 " + p + "_scaleOffset;\n"
         "uniform bool " + p + "_repeatX;\n"
         "vec3 " + p + "_coordinates(vec2 lonlat) {\n"
         "  vec3 m = " + projection.glslFunction() + "(lonlat, " + p + "_projectionA, " + p + "_projectionB);\n"
         "  return vec3(m.xy * " + p + "_mapToTexture.xz + " + p + "_mapToTexture.yw, m.z);\n"
         "}\n"
         "vec2 " + p + "_step(vec3 at, vec2 lonlat, vec2 step) {\n"
         "  return footprintStep(at, " + p + "_coordinates(steppedLonlat(lonlat, step)),\n"
         "                       " + p + "_coordinates(steppedLonlat(lonlat, -step)), " + p + "_repeatX);\n"
         "}\n"
         "vec4 " + p + "(SurfacePoint p) {\n"
         "  vec3 uv = " + p + "_coordinates(p.lonlat);\n"
         "  if (!insideTexture(uv, " + p + "_repeatX)) return vec4(0.0);\n"
         "  vec4 t = sampleFootprint(" + p + "_texture, uv.xy, " + p + "_step(uv, p.lonlat, p.lonlatDx),\n"
         "                           " + p + "_step(uv, p.lonlat, p.lonlatDy), " + p + "_repeatX);\n"
         "  if (" + std::string(colour ? "t.a" : "t.g") + " <= 0.0) return vec4(0.0);\n"
         "  return " + value + ";\n"
         "}\n";
}

void RasterLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  units.bind(program, prefix_ + "_texture", texture_.id());
  program.set(prefix_ + "_projectionA", uniforms_.projection[0]);
  program.set(prefix_ + "_projectionB", uniforms_.projection[1]);
  program.set(prefix_ + "_mapToTexture", uniforms_.mapToTexture);
  program.set(prefix_ + "_scaleOffset", glm::vec2(float(scale_), float(offset_)));
  program.set(prefix_ + "_repeatX", uniforms_.repeatX ? 1 : 0);
}

}  // namespace strata
