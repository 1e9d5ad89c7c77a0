// Each node on its own: its id, its map, its type and its keys.
#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

using NodesTest = PipelineTest;

TEST_F(NodesTest, NodeThatIsNotAMap) {
  const Error error = parseError(withNodes("  imagery: source.gdal\n"));
  EXPECT_EQ(error.problem(), "node 'imagery' must be a map with a 'type', got 'source.gdal'");
  EXPECT_EQ(error.fix(), "write it as `imagery: {type: source.gdal, ...}`");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.where().node, "imagery");
}

TEST_F(NodesTest, NodeWithoutType) {
  const Error error = parseError(withNodes(kFrameNodes + "  relief: {path: relief.gtx}\n"));
  EXPECT_EQ(error.problem(), "node 'relief' has no 'type'");
  EXPECT_NE(error.fix().find("strata plugins"), std::string::npos) << error.fix();
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.where().node, "relief");
}

TEST_F(NodesTest, UnknownTypeSuggestsARegisteredOneAndHowToListThem) {
  const Error error = parseError(withNodes("  imagery: {type: source.gdl, path: earth.jpg}\n"));
  EXPECT_EQ(error.problem(), "unknown node type 'source.gdl'; did you mean 'source.gdal'?");
  EXPECT_EQ(error.fix(), "run `strata plugins` to see the node types available");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 19);
  EXPECT_EQ(error.where().node, "imagery");
}

TEST_F(NodesTest, UnknownTypeFarFromAnyHasNoSuggestion) {
  const Error error = parseError(withNodes("  sky: {type: atmosphere.rayleigh}\n"));
  EXPECT_EQ(error.problem(), "unknown node type 'atmosphere.rayleigh'");
}

TEST_F(NodesTest, TypeMustBeText) {
  const Error error = parseError(withNodes("  sky: {type: [source.gdal]}\n"));
  EXPECT_EQ(error.problem(), "'type' of node 'sky' expects text, got a list");
}

TEST_F(NodesTest, UnknownKeySuggestsAPortOrParameter) {
  const Error error = parseError(withNodes("  relief: {type: source.gdal, path: relief.gtx, scael: 300}\n"));
  EXPECT_EQ(error.problem(), "node 'relief' (source.gdal) has no input or parameter 'scael'; did you mean 'scale'?");
  EXPECT_EQ(error.fix(),
            "source.gdal takes no inputs and the parameters 'path', 'kind', 'scale'; "
            "`strata plugins --describe source.gdal` explains them");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 49);
  EXPECT_EQ(error.where().node, "relief");
}

TEST_F(NodesTest, UnknownKeySuggestsAnInput) {
  const Error error = parseError(withNodes("  frame: {type: output.image, geometry: terrain, sruface: [a]}\n"));
  EXPECT_NE(error.problem().find("did you mean 'surface'?"), std::string::npos) << error.what();
  EXPECT_NE(error.fix().find("the inputs 'geometry', 'surface' and the parameters 'title', 'size'"), std::string::npos)
      << error.fix();
}

TEST_F(NodesTest, DuplicateNodeIds) {
  // yaml-cpp keeps both entries; without this check the second 'imagery' would silently be lost.
  const Error error = parseError(withNodes(kFrameNodes + "  imagery: {type: source.gdal, path: relief.gtx}\n"));
  EXPECT_EQ(error.problem(), "node id 'imagery' appears twice; it is first at " + pipelineFile().string() + ":3:3");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 3);
}

TEST_F(NodesTest, DuplicateKeyInANode) {
  const Error error = parseError(withNodes("  relief: {type: source.gdal, path: relief.gtx, scale: 1, scale: 2}\n"));
  EXPECT_NE(error.problem().find("key 'scale' appears twice"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().column, 59);
  EXPECT_EQ(error.where().node, "relief");
}

TEST_F(NodesTest, IdMustStartWithALetter) {
  const Error error = parseError(withNodes("  3d-terrain: {type: geometry.icosahedral}\n"));
  EXPECT_EQ(error.problem(), "node id '3d-terrain' is not a valid identifier");
  EXPECT_EQ(error.fix(), "start the id with a letter and use only letters, digits, '_' and '-'");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 3);
}

TEST_F(NodesTest, IdMayNotHoldOtherCharacters) {
  for (const char* id : {"my.relief", "my relief", "relief!", "\"\"", "_relief"}) {
    const Error error = parseError(withNodes(std::string("  ") + id + ": {type: geometry.icosahedral}\n"));
    EXPECT_NE(error.problem().find("is not a valid identifier"), std::string::npos) << id << ": " << error.what();
  }
}

TEST_F(NodesTest, IdMayHoldLettersDigitsUnderscoresAndDashes) {
  const Pipeline pipeline =
      parse(withNodes("  Imagery_2-b: {type: source.gdal, path: earth.jpg}\n"
                      "  terrain: {type: geometry.icosahedral}\n"
                      "  frame: {type: output.image, geometry: terrain, surface: Imagery_2-b}\n"));
  EXPECT_NE(pipeline.find("Imagery_2-b"), nullptr);
}

TEST_F(NodesTest, IdMustBeAName) {
  const Error error = parseError(withNodes("  ? [a, b]\n  : {type: geometry.icosahedral}\n"));
  EXPECT_EQ(error.problem(), "a key must be a name, got a list");
  EXPECT_EQ(error.where().line, 3);
}

}  // namespace
}  // namespace strata::testing
