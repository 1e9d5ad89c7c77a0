// The whole loader on valid pipelines, the file itself, and the top level of the format.
#include <sys/stat.h>

#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

const std::string kExample =
    "strata: 1\n"
    "body: {name: Earth, radius: 6371000}\n"
    "camera: {lon: 10, lat: 20, altitude: 2.0e7, heading: 0, tilt: 0, fov: 45}\n"
    "nodes:\n"
    "  imagery: {type: source.gdal, path: earth.jpg, kind: color}\n"
    "  relief:  {type: source.gdal, path: relief.gtx, kind: height, scale: 300}\n"
    "  terrain: {type: geometry.icosahedral, height: relief}\n"
    "  frame:   {type: output.image, geometry: terrain, surface: [imagery]}\n";

std::vector<std::string> idsOf(const Pipeline& pipeline) {
  std::vector<std::string> ids;
  for (const auto& node : pipeline.nodes) ids.push_back(node.id);
  return ids;
}

using LoaderTest = PipelineTest;

TEST_F(LoaderTest, ExampleReadsBodyAndCamera) {
  const Pipeline pipeline = parse(kExample);
  EXPECT_EQ(pipeline.file, pipelineFile());
  EXPECT_EQ(pipeline.version, 1);
  EXPECT_EQ(pipeline.body.name, "Earth");
  EXPECT_DOUBLE_EQ(pipeline.body.radius, 6371000.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.lon, 10.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.lat, 20.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.altitude, 2.0e7);
  EXPECT_DOUBLE_EQ(pipeline.camera.heading, 0.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.tilt, 0.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.fov, 45.0);
}

TEST_F(LoaderTest, ExampleNodesKeepTheirTypesAndInputs) {
  const Pipeline pipeline = parse(kExample);
  EXPECT_EQ(idsOf(pipeline), (std::vector<std::string>{"imagery", "relief", "terrain", "frame"}));
  const NodeDescription* frame = pipeline.find("frame");
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->type, "output.image");
  EXPECT_EQ(frame->inputs.at("geometry"), std::vector<std::string>{"terrain"});
  EXPECT_EQ(frame->inputs.at("surface"), std::vector<std::string>{"imagery"});
  EXPECT_EQ(pipeline.find("terrain")->inputs.at("height"), std::vector<std::string>{"relief"});
  EXPECT_TRUE(pipeline.find("relief")->inputs.empty());
  EXPECT_EQ(pipeline.find("missing"), nullptr);
}

TEST_F(LoaderTest, ExampleParametersHaveValuesAndLocations) {
  const Pipeline pipeline = parse(kExample);
  const NodeDescription& relief = *pipeline.find("relief");
  EXPECT_EQ(relief.where.str(), pipelineFile().string() + ":6:3 (node 'relief')");
  EXPECT_DOUBLE_EQ(relief.parameters.real("scale"), 300.0);  // written as an integer
  EXPECT_EQ(relief.parameters.string("kind"), "height");
  EXPECT_EQ(relief.parameters.path("path"), directory_.path() / "relief.gtx");
  EXPECT_EQ(relief.parameters.where("scale").line, 6);
  EXPECT_EQ(relief.parameters.where("scale").column, 71);
  EXPECT_EQ(relief.parameters.where("scale").node, "relief");
  EXPECT_EQ(relief.parameters.where("path").column, 38);
}

TEST_F(LoaderTest, DefaultsFillEveryDeclaredParameterAtTheNodesLocation) {
  const Pipeline pipeline = parse(kExample);
  const NodeDescription& imagery = *pipeline.find("imagery");
  EXPECT_DOUBLE_EQ(imagery.parameters.real("scale"), 1.0);
  EXPECT_EQ(imagery.parameters.where("scale").line, 5);
  EXPECT_EQ(imagery.parameters.where("scale").column, 3);
  const NodeDescription& terrain = *pipeline.find("terrain");
  EXPECT_EQ(terrain.parameters.integer("levels"), 6);
  EXPECT_TRUE(terrain.parameters.boolean("skirts"));
  const NodeDescription& frame = *pipeline.find("frame");
  EXPECT_EQ(frame.parameters.string("title"), "Strata");
  EXPECT_EQ(frame.parameters.reals("size"), (std::vector<double>{1920, 1080}));
}

TEST_F(LoaderTest, IntegerDefaultOfARealParameterReadsAsReal) {
  const Pipeline pipeline = parse(withNodes(kFrameNodes + "  blend: {type: composite.blend, layers: [imagery]}\n"));
  EXPECT_DOUBLE_EQ(pipeline.find("blend")->parameters.real("opacity"), 1.0);
}

TEST_F(LoaderTest, NodesComeAfterTheirInputsKeepingFileOrderOtherwise) {
  const Pipeline pipeline =
      parse(withNodes("  frame: {type: output.image, geometry: terrain, surface: [mix, imagery]}\n"
                      "  mix: {type: composite.blend, layers: [relief, imagery]}\n"
                      "  terrain: {type: geometry.icosahedral, height: relief}\n"
                      "  imagery: {type: source.gdal, path: earth.jpg}\n"
                      "  relief: {type: source.gdal, path: relief.gtx, kind: height}\n"));
  // Ready at first: imagery, relief (file order). Then mix and terrain, in file order.
  EXPECT_EQ(idsOf(pipeline), (std::vector<std::string>{"imagery", "relief", "mix", "terrain", "frame"}));
}

TEST_F(LoaderTest, BodyAndCameraAreOptional) {
  const Pipeline pipeline = parse(withNodes(kFrameNodes));
  EXPECT_EQ(pipeline.body.name, "Earth");
  EXPECT_DOUBLE_EQ(pipeline.body.radius, 6371000.0);
  EXPECT_DOUBLE_EQ(pipeline.camera.altitude, Camera{}.altitude);
  EXPECT_DOUBLE_EQ(pipeline.camera.fov, Camera{}.fov);
}

TEST_F(LoaderTest, LoadPipelineReadsAFileAndResolvesPathsBesideIt) {
  const auto file = directory_.write("recipes/earth.yaml",
                                     withNodes("  imagery: {type: source.gdal, path: ../earth.jpg}\n"
                                               "  terrain: {type: geometry.icosahedral}\n"
                                               "  frame: {type: output.image, geometry: terrain, surface: imagery}\n"));
  const Pipeline pipeline = loadPipeline(file, {}, registry_);
  EXPECT_EQ(pipeline.file, file);
  EXPECT_EQ(pipeline.find("imagery")->parameters.path("path"), directory_.path() / "earth.jpg");
  EXPECT_EQ(pipeline.find("imagery")->parameters.where("path").file, file.string());
}

TEST_F(LoaderTest, MissingFileIsReportedAtTheFile) {
  const auto file = directory_.path() / "nowhere.yaml";
  const Error error = errorFrom([&] { loadPipeline(file, {}, registry_); });
  EXPECT_EQ(error.where().file, file.string());
  EXPECT_EQ(error.where().line, 0);
  EXPECT_NE(error.problem().find("not found"), std::string::npos) << error.what();
  EXPECT_FALSE(error.fix().empty());
}

TEST_F(LoaderTest, DirectoryIsNotAPipelineFile) {
  const Error error = errorFrom([&] { loadPipeline(directory_.path(), {}, registry_); });
  EXPECT_EQ(error.where().file, directory_.path().string());
  EXPECT_NE(error.problem().find("directory"), std::string::npos) << error.what();
}

TEST_F(LoaderTest, UnreadableFileIsReportedAtTheFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
  const auto file = directory_.write("locked.yaml", withNodes(kFrameNodes));
  std::filesystem::permissions(file, std::filesystem::perms::none);
  const Error error = errorFrom([&] { loadPipeline(file, {}, registry_); });
  EXPECT_EQ(error.where().file, file.string());
  EXPECT_NE(error.problem().find("cannot read"), std::string::npos) << error.what();
  EXPECT_NE(error.fix().find("permissions"), std::string::npos);
}

TEST_F(LoaderTest, YamlSyntaxErrorHasLineAndColumn) {
  const Error error = parseError(
      "strata: 1\n"
      "nodes:\n"
      "  frame: {type: output.image, surface: [a, b}\n");
  EXPECT_EQ(error.where().file, pipelineFile().string());
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 45);
  EXPECT_NE(error.problem().find("invalid YAML"), std::string::npos) << error.what();
}

TEST_F(LoaderTest, YamlIndentationErrorHasLineAndColumn) {
  const Error error = parseError("strata: 1\n  nodes: {}\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 8);
  EXPECT_NE(error.problem().find("invalid YAML"), std::string::npos) << error.what();
}

TEST_F(LoaderTest, EmptyPipeline) {
  const Error error = parseError("# nothing yet\n");
  EXPECT_NE(error.problem().find("empty"), std::string::npos) << error.what();
  EXPECT_NE(error.fix().find("strata: 1"), std::string::npos);
}

TEST_F(LoaderTest, PipelineThatIsNotAMap) {
  const Error error = parseError("- strata: 1\n");
  EXPECT_NE(error.problem().find("must be a map"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().line, 1);
  EXPECT_EQ(error.where().column, 1);
}

TEST_F(LoaderTest, MissingVersion) {
  const Error error = parseError("# a pipeline\nnodes: {}\n");
  EXPECT_NE(error.problem().find("no 'strata' format version"), std::string::npos) << error.what();
  EXPECT_NE(error.fix().find("strata: 1"), std::string::npos);
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 1);
}

TEST_F(LoaderTest, UnsupportedVersion) {
  const Error error = parseError("nodes: {}\nstrata: 2\n");
  EXPECT_NE(error.problem().find("unsupported format version 2"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 9);
}

TEST_F(LoaderTest, VersionThatIsNotAnInteger) {
  const Error error = parseError("strata: one\nnodes: {}\n");
  EXPECT_NE(error.problem().find("expects an integer, got 'one'"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().line, 1);
  EXPECT_EQ(error.where().column, 9);
}

TEST_F(LoaderTest, UnknownTopLevelKeySuggestsTheNearestKey) {
  const Error error = parseError(withNodes(kFrameNodes) + "camara: {altitude: 5000}\n");
  EXPECT_NE(error.problem().find("unknown key 'camara'"), std::string::npos) << error.what();
  EXPECT_NE(error.problem().find("did you mean 'camera'?"), std::string::npos) << error.what();
  EXPECT_NE(
      error.fix().find("'strata', 'body', 'camera', 'cache', 'date', 'sun', 'colour', 'atmosphere', 'bodies', 'nodes'"),
      std::string::npos)
      << error.fix();
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 1);
  EXPECT_TRUE(error.where().node.empty());
}

TEST_F(LoaderTest, RepeatedTopLevelKey) {
  const Error error = parseError("strata: 1\ncamera: {fov: 30}\ncamera: {fov: 60}\nnodes: {}\n");
  EXPECT_NE(error.problem().find("key 'camera' appears twice"), std::string::npos) << error.what();
  EXPECT_NE(error.problem().find(":2:1"), std::string::npos) << error.what();  // the first one
  EXPECT_EQ(error.where().line, 3);
}

TEST_F(LoaderTest, MissingNodes) {
  const Error error = parseError("strata: 1\ncamera: {fov: 30}\n");
  EXPECT_NE(error.problem().find("no 'nodes'"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().line, 1);
}

TEST_F(LoaderTest, NodesThatAreNotAMap) {
  const Error error = parseError("strata: 1\nnodes: [imagery, frame]\n");
  EXPECT_NE(error.problem().find("'nodes' must be a map"), std::string::npos) << error.what();
  EXPECT_NE(error.problem().find("got a list"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 8);
}

}  // namespace
}  // namespace strata::testing
