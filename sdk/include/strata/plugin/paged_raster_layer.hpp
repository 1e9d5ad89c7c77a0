#pragma once
#include <memory>
#include <strata/export.hpp>
#include <string>

#include <strata/host/page_cache.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/projected_raster_layer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// A layer sampled through the page cache (docs/architecture.md, "Data and paging"): like RasterLayer, per
// sample the projection maps longitude/latitude to texture coordinates, but the texels come from the pages
// of a PageSource that the cache holds, so the raster may be far larger than GPU memory. Sources attach in
// createResources(), to the cache GpuContext::pages. One-channel layers give their slopes with their value
// (SlopedLayer), from the texels a sample filters.
class PagedRasterLayer : public ProjectedRasterLayer, public HealpixFaceLayer, public SlopedLayer {
 public:
  PagedRasterLayer(std::string nodeId, LayerKind kind);

  // On the GL thread, before the first frame. The source's pyramid covers the raster `georeference`
  // places.
  void attach(PageCache& cache, std::shared_ptr<const PageSource> source, RasterGeoreference georeference);

  std::string glsl() const override;
  // On a HEALPix pyramid's faces: sampled by face point, with no projection (HealpixFaceLayer); "" elsewhere.
  std::string faceSamplingFunction() const override;
  // One-channel kinds: <prefix>_sloped; "" for colours.
  std::string slopedSamplingFunction() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  // Its pages placed or evicted (PageCache::revision).
  std::uint64_t revision() const override;

  // A HEALPix pyramid's pages' true ranges (strata/plugin/healpix_pyramid.hpp), which faceNodeValues() reads.
  void setPageRanges(std::shared_ptr<const healpix::PageRanges> ranges) { pageRanges_ = std::move(ranges); }
  std::optional<ValueRange> faceNodeValues(int face, int level, std::int64_t ix, std::int64_t iy) const override;

 private:
  std::string faceSamplingGlsl() const;

  PageCache* cache_ = nullptr;
  PagedLayerPlacement placement_;
  std::shared_ptr<const healpix::PageRanges> pageRanges_;
};

}  // namespace strata
STRATA_EXPORTS_END
