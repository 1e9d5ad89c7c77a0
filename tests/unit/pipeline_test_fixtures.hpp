#pragma once
// Shared by the pipeline loader tests: a registry of fake node types shaped like the real plugins, a
// temporary directory with the data files they name, and helpers that parse pipeline text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <strata/host/pipeline.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata::testing {

inline NodeFactory noFactory() {
  return [](const NodeSetup&) { return std::unique_ptr<Node>(); };
}

inline ParameterDeclaration parameter(std::string name, ParameterType type, std::optional<ParameterValue> value) {
  ParameterDeclaration declaration;
  declaration.name = std::move(name);
  declaration.type = type;
  declaration.defaultValue = std::move(value);
  declaration.doc = "what " + declaration.name + " does";
  return declaration;
}

inline NodeTypeDeclaration sourceGdal() {
  NodeTypeDeclaration declaration{"source.gdal", NodeCategory::Source, "reads a raster", {}, PortType::Layer, {},
                                  noFactory()};
  auto kind = parameter("kind", ParameterType::Choice, std::string("color"));
  kind.choices = {"color", "height", "luminance", "chroma", "normal", "mask", "scalar"};
  auto scale = parameter("scale", ParameterType::Real, 1.0);
  scale.minimum = 0.0;
  scale.units = "m";
  declaration.parameters = {parameter("path", ParameterType::Path, std::nullopt), kind, scale};
  return declaration;
}

inline NodeTypeDeclaration geometryIcosahedral() {
  NodeTypeDeclaration declaration{
      "geometry.icosahedral", NodeCategory::Geometry, "a sphere of triangles", {}, PortType::Geometry, {}, noFactory()};
  declaration.inputs = {PortDeclaration{"height", PortType::Layer, {LayerKind::Height}, false, true, "heights"}};
  auto levels = parameter("levels", ParameterType::Integer, std::int64_t{6});
  levels.minimum = 1;
  levels.maximum = 24;
  declaration.parameters = {levels, parameter("skirts", ParameterType::Boolean, true)};
  return declaration;
}

inline NodeTypeDeclaration outputImage() {
  NodeTypeDeclaration declaration{"output.image", NodeCategory::Output, "writes a PNG", {}, std::nullopt, {},
                                  noFactory()};
  declaration.inputs = {PortDeclaration{"geometry", PortType::Geometry, {}, false, false, "the surface to shade"},
                        PortDeclaration{"surface", PortType::Layer, {}, true, false, "layers drawn on it"}};
  auto size = parameter("size", ParameterType::RealList, std::vector<double>{1920, 1080});
  size.count = 2;
  size.minimum = 1;
  size.units = "px";
  declaration.parameters = {parameter("title", ParameterType::String, std::string("Strata")), size};
  return declaration;
}

// A compositor with a list input, for chains and cycles of layers.
inline NodeTypeDeclaration compositeBlend() {
  NodeTypeDeclaration declaration{"composite.blend", NodeCategory::Compositor, "blends layers", {}, PortType::Layer, {},
                                  noFactory()};
  declaration.inputs = {PortDeclaration{"layers", PortType::Layer, {}, true, false, "the layers to blend"}};
  // An int64_t default for a Real, as a plugin writing `defaultValue = 1` gets.
  auto opacity = parameter("opacity", ParameterType::Real, std::int64_t{1});
  opacity.minimum = 0;
  opacity.maximum = 1;
  declaration.parameters = {opacity};
  return declaration;
}

inline PluginRegistry testRegistry() {
  PluginRegistry registry;
  for (auto& declaration : {sourceGdal(), geometryIcosahedral(), outputImage(), compositeBlend()})
    registry.add(declaration);
  return registry;
}

// A fresh directory under the system's temporary directory, removed with everything in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string name = (std::filesystem::temp_directory_path() / "strata-pipeline-XXXXXX").string();
    if (!::mkdtemp(name.data())) throw std::runtime_error("cannot create a temporary directory");
    path_ = name;
  }
  ~TemporaryDirectory() { std::filesystem::remove_all(path_); }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories((path_ / name).parent_path());
    std::ofstream(path_ / name) << text;
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

// The strata::Error `call` throws; a test failure when it throws none.
inline Error errorFrom(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "expected a strata::Error";
  return Error(SourceLocation{}, "no error");
}

// "strata: 1\nnodes:\n" + lines: the first line given is line 3 of the pipeline.
inline std::string withNodes(const std::string& lines) { return "strata: 1\nnodes:\n" + lines; }

// Three lines of nodes that make a valid pipeline: a source 'imagery', a geometry 'terrain' and an
// output 'frame'.
inline const std::string kFrameNodes =
    "  imagery: {type: source.gdal, path: earth.jpg}\n"
    "  terrain: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: terrain, surface: imagery}\n";

// Parses pipelines as if they were the file pipeline.yaml in a temporary directory that holds the data
// files earth.jpg and relief.gtx.
class PipelineTest : public ::testing::Test {
 protected:
  PipelineTest() {
    directory_.write("earth.jpg", "not really a JPEG");
    directory_.write("relief.gtx", "not really heights");
  }

  std::filesystem::path pipelineFile() const { return directory_.path() / "pipeline.yaml"; }

  Pipeline parse(const std::string& text, const std::vector<std::string>& overrides = {}) const {
    return parsePipeline(text, pipelineFile(), overrides, registry_);
  }

  Error parseError(const std::string& text, const std::vector<std::string>& overrides = {}) const {
    return errorFrom([&] { parse(text, overrides); });
  }

  TemporaryDirectory directory_;
  PluginRegistry registry_ = testRegistry();
};

}  // namespace strata::testing
