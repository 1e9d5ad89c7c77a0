#include <chrono>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/host/engine.hpp>
#include <strata/host/page_cache.hpp>
#include <strata/host/pipeline_builder.hpp>
#include <strata/log.hpp>
#include <strata/plugin/output.hpp>

#include "host_gl_state.hpp"
#include "live_parameter.hpp"
#include "node_graph.hpp"
#include "worker_pool.hpp"

namespace strata {

struct Engine::Impl {
  explicit Impl(const EngineOptions& options)
      : workers(options.workerThreads ? options.workerThreads : std::max(1u, std::thread::hardware_concurrency())) {}

  PluginRegistry registry;
  WorkerPool workers;
  ShaderLibrary shaders;
  std::unique_ptr<Pipeline> pipeline;
  std::optional<PipelineBuilder> builder;  // the pipeline's when it was built in code; none: read from its file
  std::vector<std::string> overrides;      // the pipeline's, as load() and set() were given them
  std::unique_ptr<PageCache> pages;
  std::unique_ptr<NodeGraph> graph;  // declared after what it points into: destroyed first
  HeightRange terrain;               // the graph's geometries' heights, settled when their nodes opened
  Camera camera;
  // The camera of the last frame and when it began, which the view ahead is extrapolated from.
  std::optional<std::pair<Camera, std::chrono::steady_clock::time_point>> lastCamera;
  std::optional<double> framesAhead;  // setLookAhead
  std::optional<DayNumber> date;
  FrameStatistics statistics;
  std::set<std::string> sourcesAdvised;  // the files whose page failures have been given the fix
};

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A page that cannot be read costs detail, not the frame: say so once per page, and how to check the
// file once per file.
void reportPageFailure(const PageFailure& failure, std::set<std::string>& sourcesAdvised) {
  const std::string page = "level " + std::to_string(failure.key.level) + ", page " +
                           std::to_string(failure.key.column) + ", " + std::to_string(failure.key.row);
  logWarning(
      "cannot read '" + failure.source + "' (" + page + "): " + failure.reason + "; the coarser level stands in there",
      sourcesAdvised.insert(failure.source).second
          ? "check that the file is complete and readable: gdalinfo -checksum '" + failure.source + "'"
          : "");
}

NodeDescription* findNode(Pipeline& pipeline, const std::string& id) {
  for (NodeDescription& node : pipeline.nodes)
    if (node.id == id) return &node;
  return nullptr;
}

}  // namespace

Engine::Engine(EngineOptions options) : impl_(std::make_unique<Impl>(options)) {
  impl_->registry.loadDirectories(options.pluginDirectories.empty() ? defaultPluginDirectories()
                                                                    : options.pluginDirectories);
}

Engine::~Engine() = default;

PluginRegistry& Engine::plugins() { return impl_->registry; }

void Engine::load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  install(loadPipeline(file, overrides, impl_->registry), overrides);
  impl_->builder.reset();
}

void Engine::load(const PipelineBuilder& pipeline, const std::vector<std::string>& overrides) {
  install(pipeline.build(impl_->registry, overrides), overrides);
  impl_->builder = pipeline;
}

// Makes the pipeline's nodes and their resources, then puts them in place of the loaded ones: whatever
// throws leaves the engine as it was.
void Engine::install(Pipeline loaded, const std::vector<std::string>& overrides) {
  auto pipeline = std::make_unique<Pipeline>(std::move(loaded));
  impl_->shaders.addPluginSources(impl_->registry);
  auto pages = std::make_unique<PageCache>(pipeline->cache);
  GpuContext gpu{&impl_->shaders, pages.get()};
  auto graph = std::make_unique<NodeGraph>(*pipeline, impl_->registry, impl_->workers, gpu);
  pages->allocate();
  impl_->graph.reset();  // before the cache its layers attached to
  impl_->pages = std::move(pages);
  impl_->graph = std::move(graph);
  impl_->terrain = impl_->graph->terrainHeights();
  impl_->pipeline = std::move(pipeline);
  impl_->lastCamera.reset();
  impl_->camera = impl_->pipeline->camera;
  impl_->date = impl_->pipeline->date;
  impl_->overrides = overrides;
  impl_->statistics = {};
  impl_->sourcesAdvised.clear();
}

// The loaded pipeline read again from where it came from, its file or its builder, with `overrides`.
Pipeline Engine::read(const std::vector<std::string>& overrides) const {
  if (impl_->builder) return impl_->builder->build(impl_->registry, overrides);
  return loadPipeline(impl_->pipeline->file, overrides, impl_->registry);
}

bool Engine::set(const std::string& override) {
  if (!impl_->pipeline) throw std::logic_error("Engine::set() before a pipeline was loaded");
  if (const std::optional<LiveChange> change = liveChange(override, *impl_->pipeline, impl_->registry)) {
    impl_->graph->update(change->node, change->parameters);
    findNode(*impl_->pipeline, change->node)->parameters = change->parameters;
    impl_->overrides.push_back(override);
    return true;
  }
  std::vector<std::string> overrides = impl_->overrides;
  overrides.push_back(override);
  reloadWith(read(overrides), overrides);
  return false;
}

void Engine::reload() {
  if (!impl_->pipeline) throw std::logic_error("Engine::reload() before a pipeline was loaded");
  reloadWith(read(impl_->overrides), impl_->overrides);
}

// Puts `changed` (the pipeline read again with `overrides`) in place; the camera and the date a user
// moved stay where `changed` leaves them as the pipeline had them.
void Engine::reloadWith(Pipeline changed, const std::vector<std::string>& overrides) {
  const Camera camera = impl_->camera;
  const std::optional<DayNumber> date = impl_->date;
  const bool keepCamera = changed.camera == impl_->pipeline->camera, keepDate = changed.date == impl_->pipeline->date;
  install(std::move(changed), overrides);
  if (keepCamera) impl_->camera = camera;
  if (keepDate) impl_->date = date;
}

bool Engine::loaded() const { return impl_->graph != nullptr; }

const Pipeline& Engine::pipeline() const {
  if (!impl_->pipeline) throw std::logic_error("Engine::pipeline() before a pipeline was loaded");
  return *impl_->pipeline;
}

Camera& Engine::camera() { return impl_->camera; }

View Engine::view(int width, int height) const {
  if (!impl_->graph) throw std::logic_error("Engine::view() before a pipeline was loaded");
  return makeView(impl_->pipeline->body, impl_->camera, width, height, impl_->terrain);
}

std::optional<DayNumber>& Engine::date() { return impl_->date; }

const FrameOutput& Engine::render(int width, int height) { return renderFrame(width, height, false); }

const FrameOutput& Engine::renderFrame(int width, int height, bool still) {
  if (!impl_->graph) throw std::logic_error("Engine::render() before a pipeline was loaded");
  const Pipeline& pipeline = *impl_->pipeline;
  FrameState frame{.body = &pipeline.body,
                   .view = view(width, height),
                   .index = impl_->statistics.frame,
                   .date = impl_->date,
                   .sun = sceneSun(pipeline.body, impl_->date, pipeline.sun),
                   .still = still,
                   .ahead = viewAhead(width, height, still)};
  auto start = std::chrono::steady_clock::now();
  impl_->graph->prepare(frame, impl_->workers);
  impl_->statistics.prepareMs = millisecondsSince(start);
  start = std::chrono::steady_clock::now();
  const HostGlState hostState;  // put back when the frame is done, or a node throws
  impl_->pages->update(*frame.body, frame.view, impl_->terrain, frame.index, frame.ahead);
  for (const PageFailure& failure : impl_->pages->takeFailures()) reportPageFailure(failure, impl_->sourcesAdvised);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth needs [0, 1] window depth (camera.hpp)
  impl_->graph->render(frame);
  impl_->statistics.renderMs = millisecondsSince(start);
  ++impl_->statistics.frame;
  return impl_->graph->output();
}

// The camera moved on as it moved since the last frame, for half a second at the rate frames come (or as
// setLookAhead says): FrameState::ahead.
std::optional<View> Engine::viewAhead(int width, int height, bool still) {
  constexpr double kLookAheadSeconds = 0.5;  // the paper's [Cignoni et al. 2003, §4.4]: a disk read's worth and more
  const auto now = std::chrono::steady_clock::now();
  const auto last = std::exchange(impl_->lastCamera, std::pair{impl_->camera, now});
  if (still || !last || last->first == impl_->camera) return std::nullopt;
  const double seconds = std::max(1e-3, std::chrono::duration<double>(now - last->second).count());
  const double frames = impl_->framesAhead.value_or(kLookAheadSeconds / seconds);
  return makeView(impl_->pipeline->body, cameraAhead(impl_->pipeline->body, last->first, impl_->camera, frames), width,
                  height, impl_->terrain);
}

void Engine::setLookAhead(std::optional<double> frames) { impl_->framesAhead = frames; }

const FrameOutput& Engine::renderComplete(int width, int height) { return renderLoaded(width, height, false); }

const FrameOutput& Engine::renderLoaded(int width, int height, bool still) {
  const FrameOutput* frame = &renderFrame(width, height, still);
  while (impl_->pages->loading()) {
    impl_->pages->waitForLoads();
    frame = &renderFrame(width, height, still);
  }
  return *frame;
}

const FrameOutput& Engine::renderSettled(int width, int height) {
  constexpr int kMostRenders = 256;  // a tree of 64 operations a frame refines from the whole planet to a metre
  const FrameOutput* frame = &renderLoaded(width, height, true);
  std::vector<unsigned char> before = readPixels(frame->frame());
  for (int render = 1; render < kMostRenders; ++render) {
    frame = &renderLoaded(width, height, true);
    std::vector<unsigned char> after = readPixels(frame->frame());
    if (after == before) return *frame;
    before = std::move(after);
  }
  logWarning("frame " + std::to_string(impl_->statistics.frame) + " still changed after " +
             std::to_string(kMostRenders) + " renders; it may differ between runs");
  return *frame;
}

GeometryStatistics Engine::geometryStatistics() const {
  if (!impl_->graph) throw std::logic_error("Engine::geometryStatistics() before a pipeline was loaded");
  GeometryStatistics sum;
  for (const SurfaceGeometry* geometry : impl_->graph->geometries()) {
    const GeometryStatistics one = geometry->statistics();
    sum.patches += one.patches;
    sum.vertices += one.vertices;
    sum.triangles += one.triangles;
    sum.visibilityMs += one.visibilityMs;
    sum.subdivisionMs += one.subdivisionMs;
    sum.rasterisationMs += one.rasterisationMs;
  }
  return sum;
}

std::vector<PassTime> Engine::passTimes() const {
  if (!impl_->graph) throw std::logic_error("Engine::passTimes() before a pipeline was loaded");
  return impl_->graph->passTimes();
}

const PageCacheStatistics& Engine::pageCacheStatistics() const {
  if (!impl_->pages) throw std::logic_error("Engine::pageCacheStatistics() before a pipeline was loaded");
  return impl_->pages->statistics();
}

const FrameStatistics& Engine::statistics() const { return impl_->statistics; }

}  // namespace strata
