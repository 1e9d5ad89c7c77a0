#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/atmosphere.hpp>
#include <strata/body.hpp>
#include <strata/date.hpp>
#include <strata/error.hpp>
#include <strata/host/colour_settings.hpp>
#include <strata/plugin/frame.hpp>
#include <strata/plugin/parameter.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Layer;
class SurfaceGeometry;
class FrameOutput;
class Node;
class ShaderLibrary;
class PluginRegistry;
class PageCache;

// What a node type's factory receives: its id, validated parameters and resolved inputs. The inputs were
// made before this node (the graph is built in dependency order).
struct NodeSetup {
  std::string id;
  SourceLocation where;  // the node's key in the pipeline file
  ParameterSet parameters;
  std::map<std::string, std::vector<Node*>> inputs;  // by port name; absent optional ports are missing
  const Body* body = nullptr;
  std::filesystem::path pipelineDirectory;  // relative paths in parameters resolve against this
  const PluginRegistry* plugins = nullptr;  // node types and projections (see strata/crs.hpp)
  std::optional<DayNumber> date;  // the scene's date as the pipeline gives it (`date:`); frames carry the current one
  ColourSettings colour;          // the pipeline's `colour:` (its OpenColorIO config)
  std::optional<SubsolarPoint> sun;      // the scene's sun at its date (sceneSun); frames carry the current one
  std::optional<Atmosphere> atmosphere;  // the body's air (`atmosphere:`); none: airless

  Node* input(const std::string& port) const;                          // the single node on a port, or nullptr
  const std::vector<Node*>& inputList(const std::string& port) const;  // empty when unconnected
};

// What the GL-thread hooks receive.
struct GpuContext {
  ShaderLibrary* shaders = nullptr;
  PageCache* pages = nullptr;  // where paged layers attach (strata/plugin/paged_raster_layer.hpp)
};

// One node of a pipeline. The scheduler calls, in this order:
//   open()             once, on a worker thread: read and check data (no GL)
//   createResources()  once, on the GL thread, in dependency order: textures, buffers, programs
//   prepare()          every frame, on a worker thread: CPU work for the frame (no GL)
//   render()           every frame, on the GL thread, in dependency order
// Errors a user can cause are thrown as strata::Error naming the node.
class Node {
 public:
  virtual ~Node() = default;

  virtual void open() {}
  virtual void createResources(GpuContext&) {}
  virtual void prepare(const FrameState&) {}
  virtual void render(const FrameState&) {}
  // On the GL thread between frames, when parameters declared `live` changed (Engine::set): `parameters`
  // holds every parameter, validated as at load. The node takes the new values (its layer's uniforms) for
  // the next frame; a strata::Error it throws leaves it as it was.
  virtual void update(const ParameterSet& parameters) { (void)parameters; }

  // What the node offers downstream; exactly one is non-null, matching its declared output port type.
  virtual Layer* layer() { return nullptr; }
  virtual SurfaceGeometry* geometry() { return nullptr; }
  virtual FrameOutput* output() { return nullptr; }
};

}  // namespace strata
STRATA_EXPORTS_END
