#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <strata/host/engine.hpp>
#include <strata/host/pipeline.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "pass_clock.hpp"
#include "worker_pool.hpp"

namespace strata {

// The live nodes of one pipeline, in dependency order, and the frame phases over them (docs/architecture.md,
// "How a frame is made"): prepare on the workers, render on the GL thread.
class NodeGraph {
 public:
  // Makes every node, checks the layer kinds on its inputs, reads their data on the workers (a node after
  // its inputs) and creates their GPU resources on this (the GL) thread. Throws strata::Error.
  NodeGraph(const Pipeline& pipeline, const PluginRegistry& registry, WorkerPool& workers, GpuContext& gpu);

  void prepare(const FrameState& frame, WorkerPool& workers);
  // Renders the nodes in order, each pass between two GPU timestamps.
  void render(const FrameState& frame);
  std::vector<PassTime> passTimes() const;
  // Hands node `id` its changed live parameters (Node::update), on the GL thread between frames.
  void update(const std::string& id, const ParameterSet& parameters);
  FrameOutput& output() const { return *output_; }
  std::vector<const SurfaceGeometry*> geometries() const;
  // The heights every geometry's surface keeps within, together ({0, 0} without heights).
  HeightRange terrainHeights() const;

 private:
  struct Entry {
    const NodeDescription* description;
    std::unique_ptr<Node> node;
    int depth;  // longest path from a node without inputs; nodes of one depth open in parallel
  };
  void make(const Pipeline& pipeline, const PluginRegistry& registry);
  void open(WorkerPool& workers);
  void createResources(GpuContext& gpu);

  std::vector<Entry> entries_;
  FrameOutput* output_ = nullptr;
  std::optional<PassClock> clock_;  // one pass per entry
};

}  // namespace strata
