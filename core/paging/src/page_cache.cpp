#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include <strata/gl/shader_program.hpp>
#include <strata/host/page_cache.hpp>
#include <strata/log.hpp>

#include "page_atlas.hpp"
#include "page_index.hpp"
#include "page_loader.hpp"
#include "page_selection.hpp"
#include "page_uploads.hpp"
#include "paging/page_assembly.hpp"
#include "scene_linear_pages.hpp"
#include "value_slopes_pages.hpp"

namespace strata {

using paging::LayerPage;
using paging::LoadedPage;

namespace {

struct AttachedLayer {
  std::shared_ptr<const PageSource> source;
  RasterGeoreference georeference;
  bool wrapX = false;
  std::map<PageKey, int> resident;  // page -> atlas slot
  std::set<PageKey> failed;         // never asked for again
  PageDemand demand = PageDemand::Shown;
  std::optional<int> toSceneLinear;  // the conversion its colour pages take after upload, if any
  std::uint64_t revision = 0;        // pages placed or evicted: PageCache::revision
};

}  // namespace

struct PageCache::Impl {
  explicit Impl(PageCacheSettings s) : settings(std::move(s)) {}

  void allocate();
  std::map<PageFormat, int> capacities() const;
  std::unique_ptr<paging::PageAtlas> fittingAtlas(PageFormat format, int capacity, int coarsest) const;
  void loadCoarsest();
  std::vector<paging::WantedPage> select(const Body& body, const View& view, const std::optional<View>& ahead,
                                         const HeightRange& terrain);
  void request(const std::vector<paging::WantedPage>& wanted, std::uint64_t frame);
  void uploadFinished(std::uint64_t frame, std::size_t count, bool pinned);
  void place(const LoadedPage& loaded, std::uint64_t frame, bool pinned);
  void updateStatistics(const std::vector<paging::WantedPage>& wanted);
  // Pages read and waiting for upload, plus per loader thread the page it assembles and the window it
  // reads that page from.
  std::size_t pagesHeldOnCpu() const {
    return std::size_t(settings.uploadsPerFrame) + 2 * std::size_t(settings.loaderThreads);
  }

  PageCacheSettings settings;
  std::uint64_t reserved = 0;  // of the budget, by nodes (reserve)
  std::vector<AttachedLayer> layers;
  paging::PageIndex index;
  std::map<PageFormat, std::unique_ptr<paging::PageAtlas>> atlases;
  std::unique_ptr<paging::PageUploads> uploads;
  paging::SceneLinearPages sceneLinear;
  std::unique_ptr<paging::ValueSlopesPages> valueSlopes;  // where a layer has value pages
  std::unique_ptr<paging::PageLoader> loader;             // after the layers: its threads stop before they go
  PageCacheStatistics statistics;
  std::vector<PageFailure> failures;
  std::mutex demandMutex;  // setDemand() comes from the workers' prepare()
};

std::string pageAtlasInclude(PageFormat format) {
  return format == PageFormat::Colour ? "strata/page_atlas_colour.glsl" : "strata/page_atlas_values.glsl";
}

std::string pageAtlasSampler(PageFormat format) {
  return format == PageFormat::Colour ? "strata_pageAtlasColour" : "strata_pageAtlasValues";
}

PageCache::PageCache(PageCacheSettings settings) : impl_(std::make_unique<Impl>(std::move(settings))) {}

PageCache::~PageCache() = default;

PagedLayerPlacement PageCache::attach(std::shared_ptr<const PageSource> source, const RasterGeoreference& georeference,
                                      bool wrapX) {
  if (impl_->loader) throw std::logic_error("PageCache::attach() after the first update()");
  const PagePyramid& pyramid = source->pyramid();
  const PagedLayerPlacement placement{int(impl_->layers.size()), impl_->index.add(pyramid), pyramid.levels(),
                                      pyramid.width(),           pyramid.height(),          source->format()};
  impl_->layers.push_back({std::move(source), georeference, wrapX, {}, {}});
  return placement;
}

void PageCache::reserve(std::uint64_t bytes, const SourceLocation& where) {
  Impl& cache = *impl_;
  if (cache.loader) throw std::logic_error("PageCache::reserve() after the cache allocated");
  const std::uint64_t left = cache.settings.budgetBytes - cache.reserved;
  if (bytes > left)
    throw Error(where,
                "keeps " + std::to_string(bytes >> 20) + " MiB of GPU memory, more than the " +
                    std::to_string(left >> 20) + " MiB the pipeline's page cache budget has left (of " +
                    std::to_string(cache.settings.budgetBytes >> 20) + " MiB)",
                "ask for less, or raise `cache: {budget: MiB}`");
  cache.reserved += bytes;
  cache.statistics.reservedBytes = cache.reserved;
}

void PageCache::update(const Body& body, const View& view, const HeightRange& terrain, std::uint64_t frame,
                       const std::optional<View>& ahead) {
  Impl& cache = *impl_;
  if (cache.layers.empty()) return;
  allocate();
  const std::vector<paging::WantedPage> wanted =
      cache.select(body, view, cache.settings.prefetch ? ahead : std::nullopt, terrain);
  cache.request(wanted, frame);
  cache.uploadFinished(frame, std::size_t(cache.settings.uploadsPerFrame), false);
  cache.index.upload();
  cache.updateStatistics(wanted);
}

void PageCache::allocate() {
  if (!impl_->layers.empty() && !impl_->loader) impl_->allocate();
}

void PageCache::setDemand(int layer, PageDemand demand) {
  const std::lock_guard lock(impl_->demandMutex);
  impl_->layers.at(std::size_t(layer)).demand = demand;
}

std::uint64_t PageCache::revision(int layer) const { return impl_->layers.at(std::size_t(layer)).revision; }

bool PageCache::loading() const { return impl_->loader && impl_->loader->outstanding() > 0; }

void PageCache::waitForLoads() const {
  if (impl_->loader) impl_->loader->waitForAny();
}

void PageCache::bind(ShaderProgram& program, TextureUnits& units) const {
  units.bind(program, "strata_pageIndex", impl_->index.texture());
  for (const auto& [format, atlas] : impl_->atlases)
    if (program.location(pageAtlasSampler(format)) >= 0)
      units.bind(program, pageAtlasSampler(format), atlas->texture());
}

const PageCacheStatistics& PageCache::statistics() const { return impl_->statistics; }

std::vector<PageFailure> PageCache::takeFailures() { return std::exchange(impl_->failures, {}); }

// Pages that fit each format's atlas once the upload ring, the pages held between read and upload and
// the index are paid for; the rest of the budget is shared among the formats by their numbers of layers, each
// format's share in slots of its size.
std::map<PageFormat, int> PageCache::Impl::capacities() const {
  const std::uint64_t fixed = (std::uint64_t(settings.uploadsPerFrame) + pagesHeldOnCpu()) * kPageBytes + index.bytes();
  const std::uint64_t budget = settings.budgetBytes - reserved;
  const std::uint64_t bytes = budget > fixed ? budget - fixed : 0;
  std::map<PageFormat, int> layersOf;
  for (const AttachedLayer& layer : layers) ++layersOf[layer.source->format()];
  GLint most = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &most);
  std::map<PageFormat, int> capacity;
  for (const auto& [format, count] : layersOf)
    capacity[format] = int(std::min<std::uint64_t>(
        bytes * std::uint64_t(count) / layers.size() / paging::slotBytes(format), std::uint64_t(most)));
  return capacity;
}

namespace {

std::string mebibytes(PageFormat format, int pages) {
  return std::to_string((std::uint64_t(pages) * paging::slotBytes(format)) >> 20) + " MiB";
}

}  // namespace

// The budget is what the cache asks for; a GL with less free memory gets a smaller atlas, down to the
// coarsest levels, which must always fit. Fewer slots only mean more reloads as the view moves.
std::unique_ptr<paging::PageAtlas> PageCache::Impl::fittingAtlas(PageFormat format, int capacity, int coarsest) const {
  const std::string kind = format == PageFormat::Colour ? "colour" : "value";
  std::unique_ptr<paging::PageAtlas> atlas = paging::PageAtlas::largestFitting(format, capacity, coarsest);
  if (!atlas)
    throw Error(settings.where,
                "the GPU has no memory for even the " + std::to_string(coarsest) + " pages (" +
                    mebibytes(format, coarsest) + ") of the coarsest levels of the " + kind + " layers",
                "close what else uses the GPU, or give the layers coarser overviews (strata tile)");
  if (atlas->capacity() < capacity)
    logWarning("the GPU has no memory for the page cache's " + std::to_string(capacity) + " " + kind + " pages (" +
               mebibytes(format, capacity) + "); it holds " + std::to_string(atlas->capacity()) + " (" +
               mebibytes(format, atlas->capacity()) + "), so pages are read again more often as the view moves");
  return atlas;
}

void PageCache::Impl::allocate() {
  for (const auto& [format, capacity] : capacities()) {
    int coarsest = 0;
    for (const AttachedLayer& layer : layers)
      if (layer.source->format() == format)
        coarsest += int(layer.source->pyramid().pageCount(layer.source->pyramid().levels() - 1));
    if (capacity < coarsest)
      throw Error(
          settings.where,
          "the page cache budget of " + std::to_string(settings.budgetBytes >> 20) + " MiB" +
              (reserved ? " (" + std::to_string(reserved >> 20) + " MiB of it kept by nodes for their own data)" : "") +
              " holds " + std::to_string(capacity) + " pages for " +
              (format == PageFormat::Colour ? "colour" : "value") + " layers, fewer than the " +
              std::to_string(coarsest) + " pages of their coarsest levels",
          "raise `cache: {budget: MiB}` (each page takes " + std::to_string(paging::slotBytes(format) >> 10) + " KiB)");
    atlases[format] = fittingAtlas(format, capacity, coarsest);
  }
  index.allocate();
  uploads = std::make_unique<paging::PageUploads>(settings.uploadsPerFrame);
  for (AttachedLayer& layer : layers) layer.toSceneLinear = sceneLinear.add(*layer.source);
  if (atlases.contains(PageFormat::Values)) valueSlopes = std::make_unique<paging::ValueSlopesPages>();
  loader = std::make_unique<paging::PageLoader>(settings.loaderThreads,
                                                std::size_t(settings.uploadsPerFrame + settings.loaderThreads),
                                                [this](const LayerPage& page, std::vector<std::byte>& texels) {
                                                  const AttachedLayer& layer = layers[std::size_t(page.layer)];
                                                  texels.resize(kPageBytes);
                                                  paging::assemblePage(*layer.source, page.key, layer.wrapX, texels);
                                                });
  loadCoarsest();
}

// The coarsest level of every layer, before the first frame: pinned, it stands in for everything else.
void PageCache::Impl::loadCoarsest() {
  std::vector<LayerPage> coarsest;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const PagePyramid& pyramid = layers[i].source->pyramid();
    const int top = pyramid.levels() - 1;
    for (int row = 0; row < pyramid.pagesDown(top); ++row)
      for (int column = 0; column < pyramid.pagesAcross(top); ++column)
        coarsest.push_back({int(i), {top, column, row}});
  }
  loader->replaceQueue(coarsest);
  while (loader->outstanding() > 0) {
    loader->waitForAny();
    uploadFinished(0, coarsest.size(), true);
  }
}

// The pages the view needs of the layers not idle: every shown layer's, then those the view ahead needs beyond them
// of the shown layers, then the prefetched layers', so that reading ahead, and for a later date, only fills the room
// the view leaves.
std::vector<paging::WantedPage> PageCache::Impl::select(const Body& body, const View& view,
                                                        const std::optional<View>& ahead, const HeightRange& terrain) {
  std::vector<paging::SelectableLayer> selectable;
  std::vector<std::pair<int, bool>> attached;  // per selectable: its layer, and whether it is shown
  {
    const std::lock_guard lock(demandMutex);
    for (std::size_t i = 0; i < layers.size(); ++i)
      if (layers[i].demand != PageDemand::Idle) {
        selectable.push_back({&layers[i].source->pyramid(), &layers[i].georeference, layers[i].wrapX});
        attached.emplace_back(int(i), layers[i].demand == PageDemand::Shown);
      }
  }
  std::vector<paging::WantedPage> wanted = paging::selectPages(selectable, body, view, terrain);
  const auto shown = [&attached](const paging::WantedPage& want) {
    return attached[std::size_t(want.page.layer)].second;
  };
  if (ahead) {
    std::set<LayerPage> already;
    for (const paging::WantedPage& want : wanted) already.insert(want.page);
    for (const paging::WantedPage& want : paging::selectPages(selectable, body, *ahead, terrain))
      if (shown(want) && already.insert(want.page).second)
        wanted.push_back({want.page, want.depth, want.distance, true});
  }
  const auto rank = [&shown](const paging::WantedPage& want) { return shown(want) ? (want.onlyAhead ? 1 : 0) : 2; };
  std::stable_sort(wanted.begin(), wanted.end(),
                   [&rank](const paging::WantedPage& a, const paging::WantedPage& b) { return rank(a) < rank(b); });
  for (paging::WantedPage& want : wanted) want.page.layer = attached[std::size_t(want.page.layer)].first;
  return wanted;
}

// Marks the wanted pages that are loaded as used this frame and queues the others, as many of each
// format as its atlas holds beside the pinned pages, most wanted first. Asking for more would load pages
// with nowhere to go, again every frame.
void PageCache::Impl::request(const std::vector<paging::WantedPage>& wanted, std::uint64_t frame) {
  std::map<PageFormat, int> room;
  for (const auto& [format, atlas] : atlases) room[format] = atlas->capacity() - atlas->pinned();
  std::vector<LayerPage> missing;
  for (const paging::WantedPage& want : wanted) {
    AttachedLayer& layer = layers[std::size_t(want.page.layer)];
    const PageFormat format = layer.source->format();
    const bool pinned = want.page.key.level == layer.source->pyramid().levels() - 1;
    if (!pinned && room[format] <= 0) continue;
    if (!pinned) --room[format];
    if (const auto found = layer.resident.find(want.page.key); found != layer.resident.end())
      atlases[format]->touch(found->second, frame);
    else if (!layer.failed.contains(want.page.key))
      missing.push_back(want.page);
  }
  loader->replaceQueue(missing);
}

void PageCache::Impl::uploadFinished(std::uint64_t frame, std::size_t count, bool pinned) {
  for (const LoadedPage& loaded : loader->take(count)) {
    AttachedLayer& layer = layers[std::size_t(loaded.page.layer)];
    if (!loaded.error.empty()) {
      if (layer.failed.insert(loaded.page.key).second) {
        failures.push_back({layer.source->name(), loaded.page.key, loaded.error});
        ++statistics.failed;
      }
      continue;
    }
    place(loaded, frame, pinned);
  }
}

// Puts a read page into a slot of its atlas, evicting the least recently used page if need be, converts
// it to scene-linear there where its source encodes colour otherwise, or gives a value page its slopes, and
// points the index at it. When every slot serves this frame the page is dropped; it is asked for again.
void PageCache::Impl::place(const LoadedPage& loaded, std::uint64_t frame, bool pinned) {
  AttachedLayer& layer = layers[std::size_t(loaded.page.layer)];
  paging::PageAtlas& atlas = *atlases.at(layer.source->format());
  std::optional<LayerPage> evicted;
  const std::optional<int> slot = atlas.claim(frame, evicted);
  if (!slot) return;
  if (evicted) {
    layers[std::size_t(evicted->layer)].resident.erase(evicted->key);
    index.place(evicted->layer, evicted->key, std::nullopt);
    ++layers[std::size_t(evicted->layer)].revision;
    ++statistics.evicted;
  }
  uploads->upload(atlas.texture(), atlas.format(), *slot, loaded.texels);
  if (layer.toSceneLinear) sceneLinear.convert(*layer.toSceneLinear, atlas.texture(), *slot);
  if (atlas.format() == PageFormat::Values) valueSlopes->compute(atlas.texture(), *slot);
  atlas.hold(*slot, loaded.page, frame, pinned);
  layer.resident[loaded.page.key] = *slot;
  index.place(loaded.page.layer, loaded.page.key, *slot);
  ++layer.revision;
  ++statistics.uploaded;
}

void PageCache::Impl::updateStatistics(const std::vector<paging::WantedPage>& wanted) {
  statistics.capacity = statistics.resident = statistics.pinned = 0;
  statistics.gpuBytes = uploads->bytes() + index.bytes();
  for (const auto& [format, atlas] : atlases) {
    statistics.capacity += atlas->capacity();
    statistics.resident += atlas->resident();
    statistics.pinned += atlas->pinned();
    statistics.gpuBytes += std::uint64_t(atlas->capacity()) * paging::slotBytes(format);
  }
  statistics.wanted = int(wanted.size());
  statistics.ahead = statistics.missing = 0;
  for (const paging::WantedPage& want : wanted) {
    const AttachedLayer& layer = layers[std::size_t(want.page.layer)];
    statistics.ahead += want.onlyAhead;
    statistics.missing +=
        !want.onlyAhead && !layer.resident.contains(want.page.key) && !layer.failed.contains(want.page.key);
  }
  statistics.loading = int(loader->outstanding());
  statistics.stagingBytes = (loader->peakHeld() + std::size_t(settings.loaderThreads)) * kPageBytes;  // + windows
}

}  // namespace strata
