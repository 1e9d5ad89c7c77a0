#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/host/page_cache_settings.hpp>
#include <strata/plugin/page_demand.hpp>
#include <strata/plugin/page_source.hpp>
#include <strata/plugin/raster_georeference.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class ShaderProgram;
class TextureUnits;

// What the cache holds and did; `strata render --stats` and the benchmark print it.
struct PageCacheStatistics {
  int capacity = 0;            // pages the atlases hold
  int resident = 0;            // pages in them now
  int pinned = 0;              // of those, the coarsest levels, never evicted
  int wanted = 0;              // pages the last frame asked for
  int ahead = 0;               // of those, pages only the view ahead wanted (PageCacheSettings::prefetch)
  int missing = 0;             // pages the view itself wanted that were not in place: coarser ones stood in
  int loading = 0;             // requested and not yet uploaded
  std::uint64_t uploaded = 0;  // pages copied to the GPU since the pipeline loaded
  std::uint64_t evicted = 0;
  std::uint64_t failed = 0;         // pages that could not be read (each reported once)
  std::uint64_t gpuBytes = 0;       // atlases, index and upload buffers
  std::uint64_t stagingBytes = 0;   // the most page memory held on the CPU between read and upload
  std::uint64_t reservedBytes = 0;  // of the budget, what nodes keep for their own data (PageCache::reserve)
};

// A page that could not be read. The cache never asks for it again; the coarser page it has stands in.
struct PageFailure {
  std::string source;  // PageSource::name(), usually the file
  PageKey key;
  std::string reason;
};

// Where a layer's pages are, for its GLSL (shaders/strata/paged_texture.glsl).
struct PagedLayerPlacement {
  int layer = -1;          // the cache's number for the layer (setDemand)
  unsigned indexBase = 0;  // the layer's first entry in the shared index
  int levels = 0;
  int width = 0;  // level 0, texels
  int height = 0;
  PageFormat format = PageFormat::Values;
};

// The GLSL of a page format's atlas: the file of the shader library that declares its sampler, and the
// sampler's name. A paged layer includes the one and samples the other; the cache binds it.
std::string pageAtlasInclude(PageFormat format);
std::string pageAtlasSampler(PageFormat format);

// Virtual texturing for every paged layer of a pipeline (docs/architecture.md, "Data and paging";
// [Kooima 2008, §4.3.2], after Lefohn et al.): one atlas of 514x514 pages per page format (a 2D array
// texture), one index of page references shared by all layers, so the number of layers is not bounded by
// texture units. Each frame the pages the view needs are chosen from their bounds, read on loader threads and
// uploaded through pixel buffer objects; until a page arrives the nearest coarser one stands in.
// All calls on the GL thread.
class PageCache {
 public:
  explicit PageCache(PageCacheSettings settings = {});
  ~PageCache();
  PageCache(const PageCache&) = delete;
  PageCache& operator=(const PageCache&) = delete;

  // Adds a raster. `wrapX`: it spans one period of a periodic projection, so pages on its east and west
  // edges border each other. Layers attach before the first update().
  PagedLayerPlacement attach(std::shared_ptr<const PageSource> source, const RasterGeoreference& georeference,
                             bool wrapX);
  // GPU memory a node keeps within the budget for data it pages itself (geometry.bdam's patches), asked for in
  // createResources(): the atlases share what is left. Throws strata::Error at `where` when the budget has not that
  // much left.
  void reserve(std::uint64_t bytes, const SourceLocation& where);
  // Once the layers have attached: allocates the atlases and the index, and loads the coarsest level of
  // every layer, which is pinned. Throws strata::Error when the budget cannot hold even those.
  void allocate();
  // Once a frame, before rendering: chooses the pages `view` needs, starts their loads, uploads finished
  // ones within the per-frame budget and points the index at them. Allocates first if need be. `terrain`:
  // the heights the drawn surfaces keep within (SurfaceGeometry::heights), whose ground nearest the eye
  // (groundLevelNear) distances are measured to. `ahead`: the view half a second on (FrameState::ahead), whose pages
  // are read after the view's own, into the room those leave, unless the settings' prefetch is off.
  void update(const Body& body, const View& view, const HeightRange& terrain, std::uint64_t frame,
              const std::optional<View>& ahead = std::nullopt);
  // How much `layer`'s pages are wanted from the next update() on (PageDemand). Any thread: nodes call it
  // from prepare().
  void setDemand(int layer, PageDemand demand);
  // How many times a page of `layer` has been placed or evicted: the layer's values change when it grows
  // (Layer::revision).
  std::uint64_t revision(int layer) const;
  // Whether pages the last update wanted are still on their way.
  bool loading() const;
  // Blocks until a requested page has been read (or `loading()` is false).
  void waitForLoads() const;
  // Binds the atlases and the index to the samplers paged_texture.glsl declares.
  void bind(ShaderProgram& program, TextureUnits& units) const;

  const PageCacheStatistics& statistics() const;
  // Pages that could not be read since the last call, each once, in the order it happened.
  std::vector<PageFailure> takeFailures();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata
STRATA_EXPORTS_END
