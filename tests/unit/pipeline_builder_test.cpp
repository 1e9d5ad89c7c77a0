// PipelineBuilder: a pipeline built in code is the document a file would hold, validated the same way;
// its errors name the builder (and the node) where a file's name the file, line and column.
#include <strata/host/pipeline_builder.hpp>

#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

const std::string kExample =
    "strata: 1\n"
    "body: {name: Mars, radius: 3396190}\n"
    "camera: {lon: 10, lat: 20, altitude: 2.5e7}\n"
    "date: 2004-06-15\n"
    "nodes:\n"
    "  imagery: {type: source.gdal, path: earth.jpg}\n"
    "  relief: {type: source.gdal, path: relief.gtx, kind: height, scale: 300}\n"
    "  terrain: {type: geometry.icosahedral, height: relief, levels: 7, skirts: false}\n"
    "  frame: {type: output.image, geometry: terrain, surface: [imagery, relief], size: [640, 480]}\n";

// The same pipeline, key by key.
PipelineBuilder exampleBuilder(const std::filesystem::path& directory) {
  PipelineBuilder pipeline("mars-explorer", directory);
  pipeline.set("body.name", "Mars").set("body.radius", 3396190);
  pipeline.set("camera.lon", 10).set("camera.lat", 20.0).set("camera.altitude", 2.5e7);
  pipeline.set("date", "2004-06-15");
  pipeline.node("imagery", "source.gdal", {{"path", "earth.jpg"}});
  pipeline.node("relief", "source.gdal", {{"path", "relief.gtx"}, {"kind", "height"}, {"scale", 300.0}});
  pipeline.node("terrain", "geometry.icosahedral", {{"height", "relief"}, {"levels", 7}, {"skirts", false}});
  pipeline.node("frame", "output.image",
                {{"geometry", "terrain"},
                 {"surface", std::vector<std::string>{"imagery", "relief"}},
                 {"size", std::vector<double>{640, 480}}});
  return pipeline;
}

// Everything a pipeline says but where it was written: to compare pipelines from a file and from code.
std::string contents(const Pipeline& pipeline, const PluginRegistry& registry) {
  std::string text = pipeline.body.name + " " + formatValue(pipeline.body.radius) + " camera " +
                     formatValue(pipeline.camera.lon) + " " + formatValue(pipeline.camera.lat) + " " +
                     formatValue(pipeline.camera.altitude) + " date " +
                     (pipeline.date ? formatValue(*pipeline.date) : "none") + "\n";
  for (const NodeDescription& node : pipeline.nodes) {
    text += node.id + ": " + node.type;
    for (const auto& [port, ids] : node.inputs)
      for (const std::string& id : ids) text += " " + port + "<-" + id;
    for (const ParameterDeclaration& parameter : registry.find(node.type)->parameters)
      text += " " + parameter.name + "=" + formatValue(node.parameters.value(parameter.name));
    text += "\n";
  }
  return text;
}

using PipelineBuilderTest = PipelineTest;

TEST_F(PipelineBuilderTest, BuildsWhatTheSameFileReads) {
  const Pipeline fromFile = parse(kExample);
  const Pipeline built = exampleBuilder(directory_.path()).build(registry_);
  EXPECT_EQ(contents(built, registry_), contents(fromFile, registry_));
  EXPECT_EQ(built.find("relief")->parameters.path("path"), directory_.path() / "relief.gtx");
  EXPECT_TRUE(built.file.empty()) << "built in code: no file";
  EXPECT_EQ(built.directory, directory_.path());
  EXPECT_EQ(fromFile.directory, directory_.path());
}

TEST_F(PipelineBuilderTest, ItsYamlIsAPipelineFileOfTheSamePipeline) {
  const PipelineBuilder builder = exampleBuilder(directory_.path());
  const Pipeline reread = parse(builder.yaml());
  EXPECT_EQ(contents(reread, registry_), contents(builder.build(registry_), registry_)) << builder.yaml();
  EXPECT_EQ(builder.yaml().rfind("strata: 1\n", 0), 0u) << "the format version first:\n" << builder.yaml();
}

TEST_F(PipelineBuilderTest, OverridesApplyAsToAFile) {
  const Pipeline built =
      exampleBuilder(directory_.path()).build(registry_, {"camera.altitude=5000", "nodes.relief.scale=20"});
  EXPECT_DOUBLE_EQ(built.camera.altitude, 5000.0);
  EXPECT_DOUBLE_EQ(built.find("relief")->parameters.real("scale"), 20.0);
  EXPECT_EQ(built.find("relief")->parameters.where("scale").file, "--set");
}

TEST_F(PipelineBuilderTest, ErrorsNameTheBuilderAndTheNode) {
  PipelineBuilder builder = exampleBuilder(directory_.path());
  builder.set("nodes.relief.scale", "high");
  const Error error = errorFrom([&] { builder.build(registry_); });
  EXPECT_EQ(error.where().str(), "mars-explorer (node 'relief')");
  EXPECT_NE(error.problem().find("expects a number, got 'high'"), std::string::npos) << error.what();
  EXPECT_FALSE(error.fix().empty());
}

TEST_F(PipelineBuilderTest, UnknownNodeTypeGetsADidYouMean) {
  PipelineBuilder builder = exampleBuilder(directory_.path());
  builder.node("terrain", "geometry.icosahedron");
  const Error error = errorFrom([&] { builder.build(registry_); });
  EXPECT_EQ(error.where().node, "terrain");
  EXPECT_NE(error.problem().find("geometry.icosahedral"), std::string::npos) << error.what();
}

TEST_F(PipelineBuilderTest, ADocumentWithoutNodesIsRefusedAtTheBuilder) {
  const Error error = errorFrom([&] { PipelineBuilder("empty", directory_.path()).build(registry_); });
  EXPECT_EQ(error.where().str(), "empty");
  EXPECT_NE(error.problem().find("no 'nodes'"), std::string::npos) << error.what();
}

TEST_F(PipelineBuilderTest, MissingDataFileIsResolvedAgainstTheBuildersDirectory) {
  PipelineBuilder builder = exampleBuilder(directory_.path() / "elsewhere");
  const Error error = errorFrom([&] { builder.build(registry_); });
  EXPECT_EQ(error.where().node, "imagery");
  EXPECT_NE(error.problem().find((directory_.path() / "elsewhere" / "earth.jpg").string()), std::string::npos)
      << error.what();
}

TEST_F(PipelineBuilderTest, APathWithAnEmptyKeyIsRefused) {
  PipelineBuilder builder("mars-explorer", directory_.path());
  const Error error = errorFrom([&] { builder.set("camera..altitude", 5.0); });
  EXPECT_EQ(error.where().file, "mars-explorer");
  EXPECT_NE(error.problem().find("'camera..altitude'"), std::string::npos) << error.what();
  EXPECT_NE(error.fix().find("nodes.relief.scale"), std::string::npos);
}

TEST_F(PipelineBuilderTest, APathThroughAValueIsRefused) {
  PipelineBuilder builder("mars-explorer", directory_.path());
  builder.set("camera", 5.0);
  const Error error = errorFrom([&] { builder.set("camera.altitude", 5.0); });
  EXPECT_NE(error.problem().find("'camera' holds a value"), std::string::npos) << error.what();
}

TEST_F(PipelineBuilderTest, ACopyChangesApartFromItsOriginal) {
  const PipelineBuilder original = exampleBuilder(directory_.path());
  PipelineBuilder copy = original;
  copy.set("nodes.relief.scale", 20);
  EXPECT_DOUBLE_EQ(original.build(registry_).find("relief")->parameters.real("scale"), 300.0);
  EXPECT_DOUBLE_EQ(copy.build(registry_).find("relief")->parameters.real("scale"), 20.0);
  PipelineBuilder assigned("other", directory_.path());
  assigned = original;
  assigned.set("nodes.relief.scale", 40);
  EXPECT_EQ(assigned.name(), "mars-explorer");
  EXPECT_DOUBLE_EQ(assigned.build(registry_).find("relief")->parameters.real("scale"), 40.0);
  EXPECT_DOUBLE_EQ(original.build(registry_).find("relief")->parameters.real("scale"), 300.0);
  PipelineBuilder moved = std::move(copy);
  copy.set("nodes.relief.scale", 50);  // a builder moved from is a copy still, never empty
  EXPECT_DOUBLE_EQ(moved.build(registry_).find("relief")->parameters.real("scale"), 20.0);
}

TEST_F(PipelineBuilderTest, ValuesAreReadAsTheSameTextInAFileWouldBe) {
  PipelineBuilder builder = exampleBuilder(directory_.path());
  builder.set("nodes.terrain.levels", 7.0);  // written "7": an integer
  builder.set("nodes.frame.title", "true");  // text, as `title: true` would be for a String
  const Pipeline built = builder.build(registry_);
  EXPECT_EQ(built.find("terrain")->parameters.integer("levels"), 7);
  EXPECT_EQ(built.find("frame")->parameters.string("title"), "true");
  builder.set("nodes.terrain.levels", 7.5);
  const Error error = errorFrom([&] { builder.build(registry_); });
  EXPECT_NE(error.problem().find("expects an integer, got '7.5'"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace strata::testing
