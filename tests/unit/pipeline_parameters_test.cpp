// Parameters checked against their declarations.
#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

class ParametersTest : public PipelineTest {
 protected:
  // `node` is line 6 of the pipeline, after the three of kFrameNodes.
  std::string withNode(const std::string& node) const { return withNodes(kFrameNodes + "  " + node + "\n"); }
};

TEST_F(ParametersTest, StringForARealParameter) {
  const Error error = parseError(withNode("relief: {type: source.gdal, path: relief.gtx, scale: large}"));
  EXPECT_EQ(error.problem(), "parameter 'scale' expects a number, got 'large'");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 56);
  EXPECT_EQ(error.where().node, "relief");
}

TEST_F(ParametersTest, IntegerForARealParameterIsFine) {
  const Pipeline pipeline = parse(withNode("relief: {type: source.gdal, path: relief.gtx, scale: 300}"));
  EXPECT_DOUBLE_EQ(pipeline.find("relief")->parameters.real("scale"), 300.0);
}

TEST_F(ParametersTest, RealsInTheirYamlForms) {
  for (const auto& [text, value] : std::vector<std::pair<std::string, double>>{
           {"2.5", 2.5}, {"+2.5", 2.5}, {"2.0e3", 2000.0}, {"1e-2", 0.01}, {".5", 0.5}, {"0", 0.0}}) {
    const Pipeline pipeline = parse(withNode("relief: {type: source.gdal, path: relief.gtx, scale: " + text + "}"));
    EXPECT_DOUBLE_EQ(pipeline.find("relief")->parameters.real("scale"), value) << text;
  }
}

TEST_F(ParametersTest, RealFollowedByTextIsNotANumber) {
  const Error error = parseError(withNode("relief: {type: source.gdal, path: relief.gtx, scale: 300m}"));
  EXPECT_EQ(error.problem(), "parameter 'scale' expects a number, got '300m'");
}

TEST_F(ParametersTest, FractionForAnIntegerParameter) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, levels: 1.5}"));
  EXPECT_EQ(error.problem(), "parameter 'levels' expects an integer, got '1.5'");
  EXPECT_EQ(error.fix(), "write a whole number without quotes, e.g. 3");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 47);
}

TEST_F(ParametersTest, IntegerParameter) {
  const Pipeline pipeline = parse(withNode("globe: {type: geometry.icosahedral, levels: +12}"));
  EXPECT_EQ(pipeline.find("globe")->parameters.integer("levels"), 12);
}

TEST_F(ParametersTest, YesIsNotABoolean) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, skirts: yes}"));
  EXPECT_EQ(error.problem(), "parameter 'skirts' expects true or false, got 'yes'");
  EXPECT_NE(error.fix().find("yes, no, on and off are not booleans"), std::string::npos);
  EXPECT_EQ(error.where().column, 47);
}

TEST_F(ParametersTest, NoIsNotABooleanEither) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, skirts: no}"));
  EXPECT_EQ(error.problem(), "parameter 'skirts' expects true or false, got 'no'");
}

TEST_F(ParametersTest, QuotedTrueIsNotABoolean) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, skirts: \"true\"}"));
  EXPECT_EQ(error.problem(), "parameter 'skirts' expects true or false, got quoted text \"true\"");
}

TEST_F(ParametersTest, BooleansAreTrueAndFalse) {
  EXPECT_FALSE(parse(withNode("globe: {type: geometry.icosahedral, skirts: false}"))
                   .find("globe")
                   ->parameters.boolean("skirts"));
  EXPECT_TRUE(
      parse(withNode("globe: {type: geometry.icosahedral, skirts: True}")).find("globe")->parameters.boolean("skirts"));
}

TEST_F(ParametersTest, IntegerOutOfRangeNamesTheRange) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, levels: 30}"));
  EXPECT_EQ(error.problem(), "parameter 'levels' must be in [1, 24], got 30");
  EXPECT_EQ(error.fix(), "choose a value in [1, 24]");
  EXPECT_EQ(error.where().column, 47);
}

// The value as written: through a double, 123456789012345679 came back as 123456789012345680 (issue 37).
TEST_F(ParametersTest, AnIntegerOutOfRangeIsReportedAsGiven) {
  const Error error = parseError(withNode("globe: {type: geometry.icosahedral, levels: 123456789012345679}"));
  EXPECT_EQ(error.problem(), "parameter 'levels' must be in [1, 24], got 123456789012345679");
}

TEST_F(ParametersTest, RealOutOfRangeNamesTheRangeAndUnits) {
  const Error error = parseError(withNode("relief: {type: source.gdal, path: relief.gtx, scale: -5}"));
  EXPECT_EQ(error.problem(), "parameter 'scale' must be >= 0 m, got -5 m");
  EXPECT_EQ(error.fix(), "choose a value >= 0 m");
}

TEST_F(ParametersTest, ChoiceNotAmongTheChoices) {
  const Error error = parseError(withNode("relief: {type: source.gdal, path: relief.gtx, kind: heigth}"));
  EXPECT_EQ(error.problem(),
            "parameter 'kind' is 'heigth', which is not one of 'color', 'height', 'luminance', 'chroma', 'normal', "
            "'mask', 'scalar'; did you mean 'height'?");
  EXPECT_EQ(error.fix(), "choose one of 'color', 'height', 'luminance', 'chroma', 'normal', 'mask', 'scalar'");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 55);
}

TEST_F(ParametersTest, RealListOfTheWrongLength) {
  const Error error =
      parseError(withNode("preview: {type: output.image, geometry: terrain, surface: imagery, size: [640]}"));
  EXPECT_EQ(error.problem(), "parameter 'size' expects 2 numbers, got 1");
  EXPECT_EQ(error.fix(), "give exactly 2 numbers in brackets");
  EXPECT_EQ(error.where().column, 76);
}

TEST_F(ParametersTest, RealListElementOutOfRange) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: imagery, size: [640, 0]}\n"));
  EXPECT_EQ(error.problem(), "element 2 of parameter 'size' must be >= 1 px, got 0 px");
  EXPECT_EQ(error.where().line, 5);
  EXPECT_EQ(error.where().column, 80);
}

TEST_F(ParametersTest, RealListElementThatIsNotANumber) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: imagery, size: [wide, 480]}\n"));
  EXPECT_EQ(error.problem(), "element 1 of parameter 'size' expects a number, got 'wide'");
}

TEST_F(ParametersTest, RealListThatIsNotAList) {
  const Error error =
      parseError(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                           "  terrain: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: terrain, surface: imagery, size: 640}\n"));
  EXPECT_EQ(error.problem(), "parameter 'size' expects a list of numbers, got '640'");
}

TEST_F(ParametersTest, RealList) {
  const Pipeline pipeline =
      parse(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                      "  terrain: {type: geometry.icosahedral}\n"
                      "  frame: {type: output.image, geometry: terrain, surface: imagery, size: [640, 480.5]}\n"));
  EXPECT_EQ(pipeline.find("frame")->parameters.reals("size"), (std::vector<double>{640, 480.5}));
}

TEST_F(ParametersTest, StringTakesAnyScalar) {
  const Pipeline pipeline =
      parse(withNodes("  imagery: {type: source.gdal, path: earth.jpg}\n"
                      "  terrain: {type: geometry.icosahedral}\n"
                      "  frame: {type: output.image, geometry: terrain, surface: imagery, title: 2024}\n"));
  EXPECT_EQ(pipeline.find("frame")->parameters.string("title"), "2024");
}

TEST_F(ParametersTest, MissingRequiredParameter) {
  const Error error = parseError(withNode("relief: {type: source.gdal, kind: height}"));
  EXPECT_EQ(error.problem(), "node 'relief' (source.gdal) is missing required parameter 'path' (path): what path does");
  EXPECT_EQ(error.fix(), "add `path: VALUE` to the node");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.where().node, "relief");
}

TEST_F(ParametersTest, RelativePathResolvesAgainstThePipelinesDirectory) {
  directory_.write("data/moon.tif", "");
  const Pipeline pipeline = parse(withNode("moon: {type: source.gdal, path: data/../data/moon.tif}"));
  EXPECT_EQ(pipeline.find("moon")->parameters.path("path"), directory_.path() / "data" / "moon.tif");
  EXPECT_TRUE(pipeline.find("moon")->parameters.path("path").is_absolute());
}

TEST_F(ParametersTest, AbsolutePathIsKept) {
  const auto file = directory_.write("elsewhere/moon.tif", "");
  const Pipeline pipeline = parse(withNode("moon: {type: source.gdal, path: " + file.string() + "}"));
  EXPECT_EQ(pipeline.find("moon")->parameters.path("path"), file);
}

TEST_F(ParametersTest, PathToAMissingFile) {
  const Error error = parseError(withNode("moon: {type: source.gdal, path: data/moon.tif}"));
  EXPECT_EQ(error.problem(), "parameter 'path': file not found: " + (directory_.path() / "data/moon.tif").string());
  EXPECT_EQ(error.fix(),
            "check the spelling; relative paths are read from the pipeline's directory " + directory_.path().string());
  EXPECT_EQ(error.where().line, 6);
  EXPECT_EQ(error.where().column, 35);
  EXPECT_EQ(error.where().node, "moon");
}

TEST_F(ParametersTest, EmptyPath) {
  const Error error = parseError(withNode("moon: {type: source.gdal, path: \"\"}"));
  EXPECT_EQ(error.problem(), "parameter 'path' is empty");
}

}  // namespace
}  // namespace strata::testing
