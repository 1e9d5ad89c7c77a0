#include "node_graph.hpp"

#include <algorithm>
#include <map>

#include <strata/plugin/geometry.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/node_type.hpp>

#include "node_failure.hpp"

namespace strata {

std::vector<const SurfaceGeometry*> NodeGraph::geometries() const {
  std::vector<const SurfaceGeometry*> found;
  for (const Entry& entry : entries_)
    if (const SurfaceGeometry* geometry = entry.node->geometry()) found.push_back(geometry);
  return found;
}
HeightRange NodeGraph::terrainHeights() const {
  HeightRange terrain;
  for (const SurfaceGeometry* geometry : geometries()) {
    const HeightRange heights = geometry->heights();
    terrain = {std::min(terrain.lowest, heights.lowest), std::max(terrain.highest, heights.highest)};
  }
  return terrain;
}

namespace {

bool accepts(const PortDeclaration& port, LayerKind kind) {
  return port.kinds.empty() || std::find(port.kinds.begin(), port.kinds.end(), kind) != port.kinds.end();
}

std::string kindList(const std::vector<LayerKind>& kinds) {
  std::string list;
  for (LayerKind kind : kinds) list += std::string(list.empty() ? "" : " or ") + toString(kind);
  return list;
}

// The layer kinds on a node's inputs, which are only known once the upstream nodes exist.
void checkInputKinds(const NodeDescription& node, const NodeTypeDeclaration& type, const NodeSetup& setup) {
  for (const auto& [portName, upstream] : setup.inputs) {
    const PortDeclaration* port = type.findInput(portName);
    if (!port || port->type != PortType::Layer) continue;
    for (std::size_t i = 0; i < upstream.size(); ++i) {
      const Layer* layer = upstream[i]->layer();
      const std::string& upstreamId = node.inputs.at(portName)[i];
      const SourceLocation& where = node.inputLocations.at(portName)[i];
      if (!layer)
        throw Error(where, "input '" + portName + "' refers to '" + upstreamId + "', which offers no layer",
                    "connect a source or compositor node to '" + portName + "'");
      if (!accepts(*port, layer->kind()))
        throw Error(where,
                    "input '" + portName + "' takes a " + kindList(port->kinds) + " layer, but '" + upstreamId +
                        "' is a " + toString(layer->kind()) + " layer",
                    "connect a " + kindList(port->kinds) + " layer, or change '" + upstreamId + "' (its `kind`)");
    }
  }
}

}  // namespace

NodeGraph::NodeGraph(const Pipeline& pipeline, const PluginRegistry& registry, WorkerPool& workers, GpuContext& gpu) {
  make(pipeline, registry);
  open(workers);
  createResources(gpu);
  clock_.emplace(entries_.size());
}

void NodeGraph::make(const Pipeline& pipeline, const PluginRegistry& registry) {
  std::map<std::string, std::size_t> index;
  for (const NodeDescription& description : pipeline.nodes) {
    const NodeTypeDeclaration& type = *registry.find(description.type);
    NodeSetup setup{description.id,
                    description.where,
                    description.parameters,
                    {},
                    &pipeline.body,
                    pipeline.directory,
                    &registry,
                    pipeline.date,
                    pipeline.colour,
                    sceneSun(pipeline.body, pipeline.date, pipeline.sun),
                    pipeline.atmosphere};
    int depth = 0;
    for (const auto& [port, ids] : description.inputs)
      for (const std::string& id : ids) {
        const Entry& upstream = entries_[index.at(id)];
        setup.inputs[port].push_back(upstream.node.get());
        depth = std::max(depth, upstream.depth + 1);
      }
    checkInputKinds(description, type, setup);
    auto node = guardNode(description, "could not be made", [&] { return type.create(setup); });
    if (type.category == NodeCategory::Output) output_ = node->output();
    index[description.id] = entries_.size();
    entries_.push_back({&description, std::move(node), depth});
  }
}

void NodeGraph::open(WorkerPool& workers) {
  int deepest = 0;
  for (const Entry& entry : entries_) deepest = std::max(deepest, entry.depth);
  for (int depth = 0; depth <= deepest; ++depth) {
    std::vector<std::function<void()>> tasks;
    for (Entry& entry : entries_)
      if (entry.depth == depth)
        tasks.push_back(
            [&entry] { guardNode(*entry.description, "could not read its data", [&] { entry.node->open(); }); });
    workers.runAll(std::move(tasks));
  }
}

void NodeGraph::createResources(GpuContext& gpu) {
  for (Entry& entry : entries_)
    guardNode(*entry.description, "could not create its GPU resources", [&] { entry.node->createResources(gpu); });
}

void NodeGraph::prepare(const FrameState& frame, WorkerPool& workers) {
  std::vector<std::function<void()>> tasks;
  for (Entry& entry : entries_)
    tasks.push_back([&entry, &frame] {
      guardNode(*entry.description, "failed to prepare a frame", [&] { entry.node->prepare(frame); });
    });
  workers.runAll(std::move(tasks));
}

void NodeGraph::render(const FrameState& frame) {
  clock_->mark(0);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& entry = entries_[i];
    guardNode(*entry.description, "failed to render a frame", [&] { entry.node->render(frame); });
    clock_->mark(i + 1);
  }
}

std::vector<PassTime> NodeGraph::passTimes() const {
  const std::vector<double> milliseconds = clock_->milliseconds();
  std::vector<PassTime> passes;
  for (std::size_t i = 0; i < entries_.size(); ++i) passes.push_back({entries_[i].description->id, milliseconds[i]});
  return passes;
}

void NodeGraph::update(const std::string& id, const ParameterSet& parameters) {
  for (Entry& entry : entries_)
    if (entry.description->id == id)
      guardNode(*entry.description, "could not take its new parameters", [&] { entry.node->update(parameters); });
}

}  // namespace strata
