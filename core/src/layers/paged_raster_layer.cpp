#include <strata/gl/shader_program.hpp>
#include <strata/paged_raster_layer.hpp>

namespace strata {

PagedRasterLayer::PagedRasterLayer(std::string nodeId, LayerKind kind)
    : ProjectedRasterLayer(std::move(nodeId), kind) {}

void PagedRasterLayer::attach(PageCache& cache, std::shared_ptr<const PageSource> source,
                              RasterGeoreference georeference) {
  cache_ = &cache;
  const PagePyramid& pyramid = source->pyramid();
  place(georeference, pyramid.width(), pyramid.height());
  placement_ = cache.attach(std::move(source), georeference, repeatX());
}

std::string PagedRasterLayer::glsl() const {
  const std::string& p = prefix();
  return samplingGlsl("#include \"strata/paged_texture.glsl\"\n"
                      "#include \"" + pageAtlasInclude(placement_.format) + "\"\n"
                      "uniform uint " + p + "_indexBase;\n"
                      "uniform int " + p + "_levels;\n"
                      "uniform ivec2 " + p + "_size;\n",
                      "samplePaged(" + pageAtlasSampler(placement_.format) + ", " + p +
                          "_indexBase, " + p + "_levels, " + p + "_size, uv, stepX, stepY, repeatX)");
}

void PagedRasterLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  cache_->bind(program, units);
  bindSampling(program);
  program.set(prefix() + "_indexBase", placement_.indexBase);
  program.set(prefix() + "_levels", placement_.levels);
  program.set(prefix() + "_size", glm::ivec2(placement_.width, placement_.height));
}

}  // namespace strata
