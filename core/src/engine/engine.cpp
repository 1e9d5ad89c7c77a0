#include <chrono>
#include <thread>

#include <strata/engine.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>

#include "engine/node_graph.hpp"
#include "engine/worker_pool.hpp"

namespace strata {

struct Engine::Impl {
  explicit Impl(const EngineOptions& options)
      : workers(options.workerThreads ? options.workerThreads : std::max(1u, std::thread::hardware_concurrency())) {}

  PluginRegistry registry;
  WorkerPool workers;
  ShaderLibrary shaders;
  std::unique_ptr<Pipeline> pipeline;
  std::unique_ptr<NodeGraph> graph;  // declared after the pipeline it points into: destroyed first
  Camera camera;
  FrameStatistics statistics;
};

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Engine::Engine(EngineOptions options) : impl_(std::make_unique<Impl>(options)) {
  impl_->registry.loadDirectories(options.pluginDirectories.empty() ? defaultPluginDirectories()
                                                                    : options.pluginDirectories);
}

Engine::~Engine() = default;

PluginRegistry& Engine::plugins() { return impl_->registry; }

void Engine::load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  auto pipeline = std::make_unique<Pipeline>(loadPipeline(file, overrides, impl_->registry));
  for (const ProjectionDeclaration* projection : impl_->registry.projections())
    for (const auto& [name, source] : projection->shaderSources) impl_->shaders.add(name, source);
  GpuContext gpu{&impl_->shaders};
  auto graph = std::make_unique<NodeGraph>(*pipeline, impl_->registry, impl_->workers, gpu);
  impl_->graph = std::move(graph);
  impl_->pipeline = std::move(pipeline);
  impl_->camera = impl_->pipeline->camera;
  impl_->statistics = {};
}

bool Engine::loaded() const { return impl_->graph != nullptr; }

const Pipeline& Engine::pipeline() const {
  if (!impl_->pipeline) throw std::logic_error("Engine::pipeline() before a pipeline was loaded");
  return *impl_->pipeline;
}

Camera& Engine::camera() { return impl_->camera; }

const FrameOutput& Engine::render(int width, int height) {
  if (!impl_->graph) throw std::logic_error("Engine::render() before a pipeline was loaded");
  FrameState frame{&impl_->pipeline->body, makeView(impl_->pipeline->body, impl_->camera, width, height),
                   impl_->statistics.frame};
  auto start = std::chrono::steady_clock::now();
  impl_->graph->prepare(frame, impl_->workers);
  impl_->statistics.prepareMs = millisecondsSince(start);
  start = std::chrono::steady_clock::now();
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth needs [0, 1] window depth (camera.hpp)
  impl_->graph->render(frame);
  impl_->statistics.renderMs = millisecondsSince(start);
  ++impl_->statistics.frame;
  return impl_->graph->output();
}

const FrameStatistics& Engine::statistics() const { return impl_->statistics; }

}  // namespace strata
