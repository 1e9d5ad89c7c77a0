#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/atmosphere.hpp>
#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/date.hpp>
#include <strata/error.hpp>
#include <strata/host/colour_settings.hpp>
#include <strata/host/page_cache_settings.hpp>
#include <strata/plugin/parameter.hpp>
#include <strata/sun.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// One node as the pipeline file describes it, after validation against its type's declaration.
struct NodeDescription {
  std::string id;
  std::string type;
  SourceLocation where;                                               // the node's key
  ParameterSet parameters;                                            // every declared parameter, defaults filled in
  std::map<std::string, std::vector<std::string>> inputs;             // port name -> ids of upstream nodes
  std::map<std::string, std::vector<SourceLocation>> inputLocations;  // where each of those ids is written
};

struct SceneBody;

// A validated pipeline: a body, a camera and an acyclic graph of nodes whose types are registered; or a scene
// of several bodies, each drawn by a pipeline of its own (`bodies:`), seen by one camera.
struct Pipeline {
  std::filesystem::path file;       // the file it was read from; empty when built in code (PipelineBuilder)
  std::string name;                 // what messages call it: the file's path as given, or the builder's name
  std::filesystem::path directory;  // where its relative paths resolve: the file's directory, or the builder's
  int version = 1;
  Body body;
  Camera camera;
  PageCacheSettings cache;
  ColourSettings colour;
  std::optional<DayNumber> date;         // the scene's date (`date:`), which time series show; none: not given
  std::optional<SubsolarPoint> sun;      // the scene's fixed sun (`sun:`); none: from the date (sceneSun)
  std::optional<Atmosphere> atmosphere;  // the body's air (`atmosphere:`); none: airless
  std::vector<NodeDescription> nodes;    // in dependency order: every node after its inputs
  // The scene's bodies, in the order written, when it has several; empty: the one `body` and its `nodes`. A
  // scene's own `body` is then the camera's body's (Camera::body), which hosts measure the camera over.
  std::vector<SceneBody> bodies;

  const NodeDescription* find(const std::string& id) const;
};

// How a body of a scene moves.
enum class BodyOrbit {
  Fixed,  // at SceneBody::position, its axes the scene's
  Moon,   // the Moon about the Earth at the scene's date (strata/moon_orbit.hpp)
};

// One body of a scene of several (`bodies:`, docs/pipelines.md).
struct SceneBody {
  std::string id;        // the key under `bodies:`, which Camera::body names
  SourceLocation where;  // that key
  // The body's own pipeline, read from its file; its date is the scene's, and its sun the scene's seen from where
  // the body stands, in its axes (where the scene places none, the body's own); its camera is unused.
  Pipeline pipeline;
  BodyOrbit orbit = BodyOrbit::Fixed;
  glm::dvec3 position{0.0};  // m, in the first body's planet-fixed axes (orbit: fixed)
};

// Reads, validates and orders a pipeline file. `overrides` are "PATH=VALUE" strings as given to --set
// (camera.altitude=5000, nodes.relief.scale=50); VALUE is read as YAML. Throws strata::Error naming the
// file, line and column and what would fix it.
Pipeline loadPipeline(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                      const PluginRegistry& registry);

// The same for pipeline text; `fileName` is used in messages and relative paths resolve against its
// directory.
Pipeline parsePipeline(const std::string& text, const std::filesystem::path& fileName,
                       const std::vector<std::string>& overrides, const PluginRegistry& registry);

// The files `pipeline` reads, for OutputRules::inputs (strata/host/output_file.hpp): its own file, every file a
// node's parameter names, and what GDAL reads for those (a VRT's sources, overviews, side-cars). A time
// series' file-name pattern (composite.temporal_blend's `files`) names no one file and is not expanded.
std::vector<std::filesystem::path> pipelineInputFiles(const Pipeline& pipeline);

}  // namespace strata
STRATA_EXPORTS_END
