// How nodes connect: references, port types, the one output node and cycles.
#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

using InputsTest = PipelineTest;

TEST_F(InputsTest, ReferenceToAMissingNodeSuggestsAnId) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  relief: {type: source.gdal, path: relief.gtx, kind: height}\n"
                           "  terrain: {type: geometry.icosahedral, height: relif}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: imagery}\n"));
  EXPECT_EQ(error.problem(), "input 'height' refers to 'relif', which is not a node; did you mean 'relief'?");
  EXPECT_EQ(error.fix(), "name one of the nodes: 'frame', 'imagery', 'relief', 'terrain'");
  EXPECT_EQ(error.where().line, 5);
  EXPECT_EQ(error.where().column, 49);
  EXPECT_EQ(error.where().node, "terrain");
}

TEST_F(InputsTest, ReferenceInAListToAMissingNode) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: [imagery, clouds]}\n"));
  EXPECT_EQ(error.problem(), "input 'surface' refers to 'clouds', which is not a node");
  EXPECT_EQ(error.where().line, 5);
  EXPECT_EQ(error.where().column, 69);
}

TEST_F(InputsTest, MissingRequiredInput) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  frame: {type: output.image, surface: imagery}\n"));
  EXPECT_EQ(error.problem(),
            "node 'frame' (output.image) is missing its input 'geometry' (geometry): the surface to shade");
  EXPECT_EQ(error.fix(), "add `geometry: ID`, naming a node that offers a geometry");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.where().node, "frame");
}

TEST_F(InputsTest, EmptyListDoesNotSatisfyARequiredListInput) {
  const Error error =
      parseError(withNodes("  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: []}\n"));
  EXPECT_EQ(error.problem(),
            "node 'frame' (output.image) is missing its input 'surface' (layer list): layers drawn on it");
}

TEST_F(InputsTest, OptionalInputMayBeLeftOut) {
  const Pipeline pipeline = parse(withNodes(kFrameNodes));
  EXPECT_EQ(pipeline.find("terrain")->inputs.count("height"), 0u);
}

TEST_F(InputsTest, ListGivenToASinglePort) {
  const Error error =
      parseError(withNodes("  relief: {type: source.gdal, path: relief.gtx, kind: height}\n"
                           "  terrain: {type: geometry.icosahedral, height: [relief, relief]}\n"));
  EXPECT_EQ(error.problem(), "input 'height' takes one node, got a list");
  EXPECT_EQ(error.fix(), "give a single node id, e.g. `height: relief`");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 49);
  EXPECT_EQ(error.where().node, "terrain");
}

TEST_F(InputsTest, SingleIdGivenToAListPortIsAListOfOne) {
  const Pipeline pipeline = parse(withNodes(kFrameNodes));
  EXPECT_EQ(pipeline.find("frame")->inputs.at("surface"), std::vector<std::string>{"imagery"});
}

TEST_F(InputsTest, ListPortKeepsTheOrderGiven) {
  const Pipeline pipeline =
      parse(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                      "  relief: {type: source.gdal, path: relief.gtx}\n"
                      "  terrain: {type: geometry.icosahedral}\n"
                      "  frame: {type: output.image, geometry: terrain, surface: [relief, imagery]}\n"));
  EXPECT_EQ(pipeline.find("frame")->inputs.at("surface"), (std::vector<std::string>{"relief", "imagery"}));
}

TEST_F(InputsTest, InputThatIsNotAnId) {
  const Error error = parseError(withNodes("  terrain: {type: geometry.icosahedral, height: {node: relief}}\n"));
  EXPECT_EQ(error.problem(), "input 'height' expects a node id, got a map");
  EXPECT_EQ(error.where().column, 49);
}

TEST_F(InputsTest, NodeReferringToItself) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  mix: {type: composite.blend, layers: [imagery, mix]}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: mix}\n"));
  EXPECT_EQ(error.problem(), "node 'mix' takes its own result as input 'layers'");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 50);
  EXPECT_EQ(error.where().node, "mix");
}

TEST_F(InputsTest, CycleIsListedAndLocatedAtOneEdge) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  a: {type: composite.blend, layers: [imagery, c]}\n"
                           "  b: {type: composite.blend, layers: a}\n"
                           "  c: {type: composite.blend, layers: [b]}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: c}\n"));
  EXPECT_EQ(error.problem(), "the nodes' inputs form a cycle: a -> c -> b -> a (each takes input from the next)");
  EXPECT_NE(error.fix().find("remove one of these inputs"), std::string::npos);
  // a's reference to c
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 48);
  EXPECT_EQ(error.where().node, "a");
}

TEST_F(InputsTest, GeometryPortReferringToALayer) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  frame: {type: output.image, geometry: imagery, surface: imagery}\n"));
  EXPECT_EQ(error.problem(), "input 'geometry' takes a geometry, but node 'imagery' (source.gdal) offers a layer");
  EXPECT_EQ(error.fix(), "name a node that offers a geometry on 'geometry'");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 41);
  EXPECT_EQ(error.where().node, "frame");
}

TEST_F(InputsTest, LayerPortReferringToAGeometry) {
  const Error error =
      parseError(withNodes("  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: terrain}\n"));
  EXPECT_EQ(error.problem(),
            "input 'surface' takes a layer, but node 'terrain' (geometry.icosahedral) offers a geometry");
}

TEST_F(InputsTest, OutputNodesOfferNothing) {
  const Error error = parseError(withNodes(kFrameNodes + "  mix: {type: composite.blend, layers: frame}\n"));
  EXPECT_EQ(error.problem(),
            "input 'layers' takes a layer, but node 'frame' (output.image) offers nothing (it is an output)");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().node, "mix");
}

TEST_F(InputsTest, NoOutputNode) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  terrain: {type: geometry.icosahedral}\n"));
  EXPECT_EQ(error.problem(), "the pipeline has no output node");
  EXPECT_NE(error.fix().find("output.image"), std::string::npos);
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 3);
}

TEST_F(InputsTest, EmptyNodesHasNoOutputNode) {
  const Error error = parseError("strata: 1\nnodes: {}\n");
  EXPECT_EQ(error.problem(), "the pipeline has no output node");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 8);
}

TEST_F(InputsTest, MoreThanOneOutputNodeNamesThem) {
  const Error error =
      parseError(withNodes(kFrameNodes + "  preview: {type: output.image, geometry: terrain, surface: imagery}\n"));
  EXPECT_EQ(error.problem(), "the pipeline has 2 output nodes ('frame', 'preview'); it must have exactly one");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.where().node, "preview");
}

}  // namespace
}  // namespace strata::testing
