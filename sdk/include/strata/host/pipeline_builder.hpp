#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <strata/export.hpp>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <strata/host/pipeline.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// A value written into a pipeline built in code. It means what it would mean written in a pipeline file
// (docs/pipelines.md): 300 and 300.0 both suit a Real parameter, "2004-06-15" a date, a list of strings
// a list of node ids or of dates.
using PipelineValue =
    std::variant<bool, std::int64_t, double, std::string, std::vector<double>, std::vector<std::string>>;

// A pipeline written in code rather than in a file: the same document, key by key, validated by build()
// exactly as loadPipeline() validates a file. Errors name the builder's `name` where a file's would name
// the file and line: "mars-explorer (node 'relief'): error: ...".
//
//   strata::PipelineBuilder pipeline("mars-explorer", dataDirectory);
//   pipeline.set("body.name", "Mars").set("body.radius", 3396190.0);
//   pipeline.node("heights", "source.gdal", {{"path", "mola.tif"}, {"kind", "height"}});
//   pipeline.node("imagery", "source.gdal", {{"path", "viking.tif"}});
//   pipeline.node("globe", "geometry.icosahedral", {{"height", "heights"}});
//   pipeline.node("frame", "output.image", {{"geometry", "globe"}, {"surface", std::vector<std::string>{"imagery"}}});
//   engine.load(pipeline);
class PipelineBuilder {
 public:
  // Starts the document `strata: 1` (the format this Strata reads). Relative paths in it resolve against
  // `directory` (empty: the current directory, taken now).
  explicit PipelineBuilder(std::string name, const std::filesystem::path& directory = {});
  ~PipelineBuilder();
  // A deep copy: changing one leaves the other. Moves copy too, so that no builder is ever left empty.
  PipelineBuilder(const PipelineBuilder& other);
  PipelineBuilder& operator=(const PipelineBuilder& other);

  // Writes `value` at `path`: dot-separated keys from the top of the document, as in a --set override
  // ("camera.altitude", "nodes.relief.scale"). Maps on the way are made as needed; a value already there
  // is replaced. Throws strata::Error when a key is empty or the path goes through a value that is not
  // a map.
  PipelineBuilder& set(const std::string& path, PipelineValue value);
  // Adds node `id` of `type` with its inputs and parameters (port or parameter name, value), as
  // `nodes: {id: {type: TYPE, ...}}` would.
  PipelineBuilder& node(const std::string& id, const std::string& type,
                        const std::vector<std::pair<std::string, PipelineValue>>& entries = {});

  const std::string& name() const;
  const std::filesystem::path& directory() const;
  // The document as a pipeline file's YAML: to save it, or to show what was built.
  std::string yaml() const;
  // Validates and orders the document as loadPipeline() does a file, with the --set `overrides` applied
  // first. The result's `file` is empty. Throws strata::Error naming the builder and, where the problem
  // belongs to one, the node.
  Pipeline build(const PluginRegistry& registry, const std::vector<std::string>& overrides = {}) const;

 private:
  struct Document;
  void assign(const std::vector<std::string>& keys, const PipelineValue& value, const std::string& path);
  std::string name_;
  std::filesystem::path directory_;
  std::unique_ptr<Document> document_;
};

}  // namespace strata
STRATA_EXPORTS_END
