#include <algorithm>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/paged_raster_layer.hpp>

#include "layers/healpix_page_caps.hpp"

namespace strata {
namespace {

// Whether fragment stages let the sampler filter the atlas (slotBilinear in paged_texture.glsl): colour pages
// only, whose atlas filters linearly; heights and values are filtered by hand.
std::string bySamplerOf(PageFormat format) { return format == PageFormat::Colour ? "true" : "false"; }

}  // namespace

PagedRasterLayer::PagedRasterLayer(std::string nodeId, LayerKind kind)
    : ProjectedRasterLayer(std::move(nodeId), kind) {}

void PagedRasterLayer::attach(PageCache& cache, std::shared_ptr<const PageSource> source,
                              RasterGeoreference georeference) {
  cache_ = &cache;
  const PagePyramid& pyramid = source->pyramid();
  place(georeference, pyramid.width(), pyramid.height());
  if (pageRanges_ && onHealpixFaces()) setBlockCaps(pageCapsOf(*pageRanges_, georeference, pyramid.height()));
  placement_ = cache.attach(std::move(source), georeference, repeatX());
}

std::string PagedRasterLayer::glsl() const {
  const std::string& p = prefix();
  return samplingGlsl(
             "#include \"strata/paged_texture.glsl\"\n"
             "#include \"" +
                 pageAtlasInclude(placement_.format) +
                 "\"\n"
                 "uniform uint " +
                 p +
                 "_indexBase;\n"
                 "uniform int " +
                 p + "_levels;\n",
             "samplePaged(" + pageAtlasSampler(placement_.format) + ", " + bySamplerOf(placement_.format) + ", " + p +
                 "_indexBase, " + p + "_levels, " + p + "_size, " + p + "_texel(at, p), stepX, stepY, repeatX, " +
                 (onHealpixFaces() ? p + "_size.y" : "0") + ")",
             true) +
         (onHealpixFaces() ? faceSamplingGlsl() : "");
}

std::string PagedRasterLayer::faceSamplingFunction() const { return onHealpixFaces() ? prefix() + "_face" : ""; }

std::string PagedRasterLayer::slopedSamplingFunction() const { return oneChannel() ? prefix() + "_sloped" : ""; }

// Texel positions straight from the face point, in level-0 texels of the strip (nside = its height): exact for
// the dyadic face points geometry.healpix makes, so that two nodes sharing a vertex on a face edge, each in its
// own face, filter the same texels with the same weights (its own edge texel and the border's, half and half).
std::string PagedRasterLayer::faceSamplingGlsl() const {
  const std::string& p = prefix();
  return "vec4 " + p +
         "_face(vec3 point, float footprint) {\n"
         "  float nside = float(" +
         p +
         "_size.y);\n"
         "  vec2 texel = vec2((point.x + point.y) * nside, (1.0 - point.z) * nside);\n"
         "  return " +
         p + "_value(samplePagedTexels(" + pageAtlasSampler(placement_.format) + ", " + bySamplerOf(placement_.format) +
         ", pagedLevels(" + p + "_indexBase, " + p + "_levels, footprint * nside), " + p +
         "_size, texelAddressOf(texel), int(point.x)));\n"
         "}\n";
}

std::optional<ValueRange> PagedRasterLayer::faceNodeValues(int face, int level, std::int64_t ix,
                                                           std::int64_t iy) const {
  if (!pageRanges_) return std::nullopt;
  const healpix::PageRanges::Range raw = pageRanges_->overNode(face, level, ix, iy);
  if (raw.least > raw.greatest) return ValueRange{};  // no data at all: the sphere
  ValueRange values = transformed(raw.least, raw.greatest);
  if (raw.uncovered) values = {std::min(values.least, 0.0), std::max(values.greatest, 0.0)};
  return values;
}

void PagedRasterLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  cache_->bind(program, units);
  bindSampling(program);
  program.set(prefix() + "_indexBase", placement_.indexBase);
  program.set(prefix() + "_levels", placement_.levels);
}

void PagedRasterLayer::setPageDemand(PageDemand demand) const {
  if (cache_) cache_->setDemand(placement_.layer, demand);
}

std::uint64_t PagedRasterLayer::revision() const { return cache_ ? cache_->revision(placement_.layer) : 0; }

}  // namespace strata
