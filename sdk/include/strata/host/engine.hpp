#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/camera.hpp>
#include <strata/host/page_cache.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/output.hpp>
#include <strata/plugin/plugin_registry.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class PipelineBuilder;

struct EngineOptions {
  std::vector<std::filesystem::path> pluginDirectories;  // empty: defaultPluginDirectories()
  unsigned workerThreads = 0;                            // 0: one per hardware thread
};

// One node's render pass in a frame: the GPU time from the end of the pass before it to the end of its own.
struct PassTime {
  std::string node;    // the node's id in the pipeline
  double gpuMs = 0.0;  // GL_TIMESTAMP queries around the pass (the page uploads before the first are not in it)
};

// Per-frame timings and counts.
struct FrameStatistics {
  std::uint64_t frame = 0;
  double prepareMs = 0.0;  // CPU phase, all nodes, on the workers
  double renderMs = 0.0;   // GL phase, all nodes, CPU time to submit (GPU time is not waited for)
};

// Loads pipelines and renders their frames into framebuffers, on the caller's current OpenGL 4.5 context.
// All calls come from the thread that owns that context.
class Engine {
 public:
  explicit Engine(EngineOptions options = {});
  ~Engine();
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  PluginRegistry& plugins();

  // Validates the pipeline, makes its nodes, reads their data (worker threads) and creates their GPU
  // resources. Throws strata::Error; on failure the previously loaded pipeline stays.
  void load(const std::filesystem::path& pipeline, const std::vector<std::string>& overrides = {});
  // The same for a pipeline built in code (strata/host/pipeline_builder.hpp). The engine keeps a copy of the
  // builder, which set() and reload() build again; later changes to `pipeline` reach the engine only
  // through another load().
  void load(const PipelineBuilder& pipeline, const std::vector<std::string>& overrides = {});
  bool loaded() const;
  // Changes the loaded pipeline as an override "PATH=VALUE" would (--set; nodes.relief.azimuth=135),
  // validated the same way. A node parameter declared live (ParameterDeclaration::live) takes effect in the
  // next frame with nothing rebuilt (Node::update); anything else loads the pipeline again with the change,
  // keeping the camera and the date unless the change is to them. Returns whether the change was live.
  // Throws strata::Error as load() does; the pipeline then stays as it was.
  bool set(const std::string& override);
  // Loads the pipeline's file again, with the overrides load() and set() were given: after the file was
  // edited. A pipeline built in code is built again from the engine's copy, which reads its data files
  // again. Keeps the camera and the date unless the file changed them. Throws strata::Error as load()
  // does; the pipeline then stays as it was.
  void reload();
  const Pipeline& pipeline() const;

  Camera& camera();  // starts as the pipeline's camera; change it between frames
  // The body the camera is placed over: the pipeline's, or in a scene of several bodies (`bodies:`) the one
  // Camera::body names. Throws strata::Error where the camera names no body of the scene.
  const Body& cameraBody() const;
  // The view render() draws the camera from at width x height, over the terrain of the camera's body: for
  // picking, and for comparing a frame with a reference computed from its rays.
  View view(int width, int height) const;
  // The scene's date, which time series show (composite.temporal_blend): starts as the pipeline's `date:`;
  // change it between frames to step or animate through time with no reload.
  std::optional<DayNumber>& date();
  // Renders one frame of width x height pixels and returns the pipeline's output. Paged layers show what
  // the cache holds: pages still loading are stood in for by coarser ones. The caller's framebuffer
  // bindings, viewport and clip control are as they were when it returns; other GL state (programs,
  // textures, depth test, blending) is the engine's, for the caller's drawing to set as it needs.
  const FrameOutput& render(int width, int height);
  // Renders until every page the view wants is loaded (or found unreadable) and returns the last frame:
  // for still images.
  const FrameOutput& renderComplete(int width, int height);
  // Renders still frames (FrameState::still) until every page is in and two frames in a row are the same,
  // and returns the last: the frame of a sequence whose camera moves (a camera path, a synchronous
  // benchmark), the same on every run however the page loaders are timed. Logs a warning (strata/log.hpp),
  // and returns the last, when 256 renders did not settle it.
  const FrameOutput& renderSettled(int width, int height);
  // How far ahead FrameState::ahead looks, for the prefetch of pages and patches: the camera's move since the last
  // frame repeated `frames` times. Unset, the default: half a second [Cignoni et al. 2003, §4.4] at the interval
  // measured between the last two frames. Tests and offline runs that want the same reads on every run set it.
  void setLookAhead(std::optional<double> frames);
  const FrameStatistics& statistics() const;
  // The geometry generators' statistics for the last frame, summed; waits for the GPU to finish it.
  GeometryStatistics geometryStatistics() const;
  // Each node's render pass in the last frame, in the order they ran; waits for the GPU to finish it.
  std::vector<PassTime> passTimes() const;
  const PageCacheStatistics& pageCacheStatistics() const;

 private:
  struct BodyGraph;
  const BodyGraph& cameraGraph() const;
  const FrameOutput& renderFrame(int width, int height, bool still);
  FrameState frameOf(const BodyGraph& body, const View& view, const std::optional<View>& ahead, bool still,
                     const std::optional<SubsolarPoint>& sun) const;
  void prepareBody(BodyGraph& body, const FrameState& frame);
  const FrameOutput& drawBody(BodyGraph& body, const FrameState& frame);
  const FrameOutput& renderBody(BodyGraph& body, const View& view, const std::optional<View>& ahead, bool still);
  const FrameOutput& renderScene(const View& seen, const std::optional<View>& ahead, bool still);
  const FrameOutput& renderLoaded(int width, int height, bool still);
  std::optional<View> viewAhead(int width, int height, bool still);
  void install(Pipeline pipeline, const std::vector<std::string>& overrides);
  Pipeline read(const std::vector<std::string>& overrides) const;
  void reloadWith(Pipeline changed, const std::vector<std::string>& overrides);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata
STRATA_EXPORTS_END
