#include <algorithm>
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
#include "pipeline/scene_placement.hpp"
#include "scene_frame.hpp"
#include "worker_pool.hpp"

namespace strata {

// One body's nodes and what feeds them: a pipeline of one body has one, a scene of several bodies one per body.
struct Engine::BodyGraph {
  const Pipeline* pipeline = nullptr;  // the body's own: the engine's pipeline, or one of its scene's bodies'
  const SceneBody* placed = nullptr;   // its entry in the scene; nullptr in a pipeline of one body
  std::unique_ptr<PageCache> pages;
  std::unique_ptr<NodeGraph> graph;      // declared after the cache its layers attach to: destroyed first
  HeightRange terrain;                   // the graph's geometries' heights, settled when their nodes opened
  std::set<std::string> sourcesAdvised;  // the files whose page failures have been given the fix
};

struct Engine::Impl {
  explicit Impl(const EngineOptions& options)
      : workers(options.workerThreads ? options.workerThreads : std::max(1u, std::thread::hardware_concurrency())) {}

  PluginRegistry registry;
  WorkerPool workers;
  ShaderLibrary shaders;
  std::unique_ptr<Pipeline> pipeline;
  std::optional<PipelineBuilder> builder;  // the pipeline's when it was built in code; none: read from its file
  std::vector<std::string> overrides;      // the pipeline's, as load() and set() were given them
  std::vector<BodyGraph> bodies;           // declared after the pipeline they point into: destroyed first
  std::unique_ptr<SceneFrame> sceneFrame;  // a scene of several bodies' frame, made with its first
  Camera camera;
  // The camera of the last frame and when it began, which the view ahead is extrapolated from.
  std::optional<std::pair<Camera, std::chrono::steady_clock::time_point>> lastCamera;
  std::optional<double> framesAhead;  // setLookAhead
  std::optional<DayNumber> date;
  FrameStatistics statistics;
  PageCacheStatistics cacheStatistics;  // the bodies' caches' together, as pageCacheStatistics() last summed them

  // Makes the nodes of `drawn`, one body's pipeline, and the page cache that feeds them.
  BodyGraph graphOf(const Pipeline& drawn, const SceneBody* placed) {
    BodyGraph body{.pipeline = &drawn, .placed = placed, .pages = std::make_unique<PageCache>(drawn.cache)};
    GpuContext gpu{&shaders, body.pages.get()};
    body.graph = std::make_unique<NodeGraph>(drawn, registry, workers, gpu);
    body.pages->allocate();
    body.terrain = body.graph->terrainHeights();
    return body;
  }
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

void addStatistics(PageCacheStatistics& sum, const PageCacheStatistics& one) {
  sum.capacity += one.capacity;
  sum.resident += one.resident;
  sum.pinned += one.pinned;
  sum.wanted += one.wanted;
  sum.ahead += one.ahead;
  sum.missing += one.missing;
  sum.loading += one.loading;
  sum.uploaded += one.uploaded;
  sum.evicted += one.evicted;
  sum.failed += one.failed;
  sum.gpuBytes += one.gpuBytes;
  sum.stagingBytes += one.stagingBytes;
  sum.reservedBytes += one.reservedBytes;
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

// Makes the pipeline's nodes and their resources, a graph per body, then puts them in place of the loaded
// ones: whatever throws leaves the engine as it was.
void Engine::install(Pipeline loaded, const std::vector<std::string>& overrides) {
  auto pipeline = std::make_unique<Pipeline>(std::move(loaded));
  impl_->shaders.addPluginSources(impl_->registry);
  std::vector<BodyGraph> bodies;
  if (pipeline->bodies.empty()) bodies.push_back(impl_->graphOf(*pipeline, nullptr));
  for (const SceneBody& body : pipeline->bodies) bodies.push_back(impl_->graphOf(body.pipeline, &body));
  impl_->bodies = std::move(bodies);
  impl_->pipeline = std::move(pipeline);
  impl_->lastCamera.reset();
  impl_->camera = impl_->pipeline->camera;
  impl_->date = impl_->pipeline->date;
  impl_->overrides = overrides;
  impl_->statistics = {};
}

// The loaded pipeline read again from where it came from, its file or its builder, with `overrides`.
Pipeline Engine::read(const std::vector<std::string>& overrides) const {
  if (impl_->builder) return impl_->builder->build(impl_->registry, overrides);
  return loadPipeline(impl_->pipeline->file, overrides, impl_->registry);
}

bool Engine::set(const std::string& override) {
  if (!impl_->pipeline) throw std::logic_error("Engine::set() before a pipeline was loaded");
  if (const std::optional<LiveChange> change = liveChange(override, *impl_->pipeline, impl_->registry)) {
    impl_->bodies.front().graph->update(change->node, change->parameters);
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

bool Engine::loaded() const { return !impl_->bodies.empty(); }

const Pipeline& Engine::pipeline() const {
  if (!impl_->pipeline) throw std::logic_error("Engine::pipeline() before a pipeline was loaded");
  return *impl_->pipeline;
}

Camera& Engine::camera() { return impl_->camera; }

const Engine::BodyGraph& Engine::cameraGraph() const {
  if (impl_->bodies.empty()) throw std::logic_error("the engine's camera asked for before a pipeline was loaded");
  for (const BodyGraph& body : impl_->bodies)
    if (!body.placed || body.placed->id == impl_->camera.body) return body;
  throw Error(SourceLocation{impl_->pipeline->name},
              "the camera is placed over '" + impl_->camera.body + "', which is not a body of the scene",
              "set Camera::body to the id of one of the scene's bodies");
}

const Body& Engine::cameraBody() const { return cameraGraph().pipeline->body; }

View Engine::view(int width, int height) const {
  const BodyGraph& body = cameraGraph();
  return makeView(body.pipeline->body, impl_->camera, width, height, body.terrain);
}

std::optional<DayNumber>& Engine::date() { return impl_->date; }

const FrameOutput& Engine::render(int width, int height) { return renderFrame(width, height, false); }

const FrameOutput& Engine::renderFrame(int width, int height, bool still) {
  const View seen = view(width, height);
  const std::optional<View> ahead = viewAhead(width, height, still);
  impl_->statistics.prepareMs = impl_->statistics.renderMs = 0.0;
  const HostGlState hostState;                   // put back when the frame is done, or a node throws
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth needs [0, 1] window depth (camera.hpp)
  const FrameOutput& output = impl_->pipeline->bodies.empty() ? renderBody(impl_->bodies.front(), seen, ahead, still)
                                                              : renderScene(seen, ahead, still);
  ++impl_->statistics.frame;
  return output;
}

// What the nodes of `body` see of this frame, from `view` in the body's axes, with the sun over `sun`.
FrameState Engine::frameOf(const BodyGraph& body, const View& view, const std::optional<View>& ahead, bool still,
                           const std::optional<SubsolarPoint>& sun) const {
  return {.body = &body.pipeline->body,
          .view = view,
          .index = impl_->statistics.frame,
          .date = impl_->date,
          .sun = sun,
          .still = still,
          .ahead = ahead,
          .transparentBackground = body.placed != nullptr};
}

// Step 1 of a frame for one body: its nodes' CPU work, on the workers.
void Engine::prepareBody(BodyGraph& body, const FrameState& frame) {
  const auto start = std::chrono::steady_clock::now();
  body.graph->prepare(frame, impl_->workers);
  impl_->statistics.prepareMs += millisecondsSince(start);
}

// Steps 2 to 5 for one body: its pages updated, its nodes rendered.
const FrameOutput& Engine::drawBody(BodyGraph& body, const FrameState& frame) {
  const auto start = std::chrono::steady_clock::now();
  body.pages->update(*frame.body, frame.view, body.terrain, frame.index, frame.ahead);
  for (const PageFailure& failure : body.pages->takeFailures()) reportPageFailure(failure, body.sourcesAdvised);
  body.graph->render(frame);
  impl_->statistics.renderMs += millisecondsSince(start);
  return body.graph->output();
}

// The frame of a pipeline of one body, lit by its sun.
const FrameOutput& Engine::renderBody(BodyGraph& body, const View& view, const std::optional<View>& ahead, bool still) {
  const FrameState frame =
      frameOf(body, view, ahead, still, sceneSun(body.pipeline->body, impl_->date, body.pipeline->sun));
  prepareBody(body, frame);
  return drawBody(body, frame);
}

// Every body's frame from the camera's view, each in the body's own axes with its own near plane and lit by
// the scene's sun as seen from where it stands (else its own), laid farthest first over space (SceneFrame). As
// [Kooima 2008, §3.1] interleaves the bodies, every body's CPU work comes before any body's drawing.
const FrameOutput& Engine::renderScene(const View& seen, const std::optional<View>& ahead, bool still) {
  const Pipeline& scene = *impl_->pipeline;
  const std::optional<SubsolarPoint> sun = sceneSun(scene.bodies.front().pipeline.body, impl_->date, scene.sun);
  const BodyPlacement from = placementOf(*cameraGraph().placed, impl_->date);
  const glm::dvec3 eye = from.centre + from.axes * seen.eye;
  std::vector<FrameState> frames;
  std::vector<double> powers;  // of the eye with respect to each body's sphere of its highest ground
  for (BodyGraph& body : impl_->bodies) {
    const BodyPlacement to = placementOf(*body.placed, impl_->date);
    const auto placed = [&](const View& view) { return viewOfBody(view, from, to, body.pipeline->body, body.terrain); };
    frames.push_back(frameOf(body, placed(seen), ahead ? std::optional<View>(placed(*ahead)) : std::nullopt, still,
                             sun ? std::optional<SubsolarPoint>(sunOver(*sun, to)) : body.pipeline->sun));
    prepareBody(body, frames.back());
    const double reach = body.pipeline->body.radius + std::max(body.terrain.highest, 0.0);
    powers.push_back(glm::dot(to.centre - eye, to.centre - eye) - reach * reach);
  }
  std::vector<std::pair<double, const Framebuffer*>> drawn;
  for (std::size_t i = 0; i < impl_->bodies.size(); ++i)
    drawn.emplace_back(powers[i], &drawBody(impl_->bodies[i], frames[i]).frame());
  std::sort(drawn.begin(), drawn.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<const Framebuffer*> farthestFirst;
  for (const auto& [power, frame] : drawn) farthestFirst.push_back(frame);
  if (!impl_->sceneFrame) impl_->sceneFrame = std::make_unique<SceneFrame>(impl_->shaders);
  impl_->sceneFrame->compose(seen.width, seen.height, farthestFirst);
  return *impl_->sceneFrame;
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
  const BodyGraph& body = cameraGraph();
  return makeView(body.pipeline->body, cameraAhead(body.pipeline->body, last->first, impl_->camera, frames), width,
                  height, body.terrain);
}

void Engine::setLookAhead(std::optional<double> frames) { impl_->framesAhead = frames; }

const FrameOutput& Engine::renderComplete(int width, int height) { return renderLoaded(width, height, false); }

const FrameOutput& Engine::renderLoaded(int width, int height, bool still) {
  const FrameOutput* frame = &renderFrame(width, height, still);
  const auto loading = [this] {
    return std::any_of(impl_->bodies.begin(), impl_->bodies.end(),
                       [](const BodyGraph& b) { return b.pages->loading(); });
  };
  while (loading()) {
    for (BodyGraph& body : impl_->bodies)
      if (body.pages->loading()) body.pages->waitForLoads();
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
  if (impl_->bodies.empty()) throw std::logic_error("Engine::geometryStatistics() before a pipeline was loaded");
  GeometryStatistics sum;
  for (const BodyGraph& body : impl_->bodies)
    for (const SurfaceGeometry* geometry : body.graph->geometries()) {
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
  if (impl_->bodies.empty()) throw std::logic_error("Engine::passTimes() before a pipeline was loaded");
  std::vector<PassTime> times;
  for (const BodyGraph& body : impl_->bodies)
    for (PassTime pass : body.graph->passTimes()) {
      if (body.placed) pass.node = body.placed->id + "." + pass.node;
      times.push_back(std::move(pass));
    }
  return times;
}

const PageCacheStatistics& Engine::pageCacheStatistics() const {
  if (impl_->bodies.empty()) throw std::logic_error("Engine::pageCacheStatistics() before a pipeline was loaded");
  if (impl_->bodies.size() == 1) return impl_->bodies.front().pages->statistics();
  PageCacheStatistics& sum = impl_->cacheStatistics;
  sum = {};
  for (const BodyGraph& body : impl_->bodies) addStatistics(sum, body.pages->statistics());
  return sum;
}

const FrameStatistics& Engine::statistics() const { return impl_->statistics; }

}  // namespace strata
