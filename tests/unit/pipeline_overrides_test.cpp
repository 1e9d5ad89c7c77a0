// --set PATH=VALUE overrides, applied to the YAML tree before validation.
#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

class OverridesTest : public PipelineTest {
 protected:
  const std::string pipeline_ = "strata: 1\ncamera: {altitude: 20000000}\nnodes:\n" + kFrameNodes;

  Error overrideError(const std::string& override) const { return parseError(pipeline_, {override}); }
};

TEST_F(OverridesTest, SetsACameraValue) {
  EXPECT_DOUBLE_EQ(parse(pipeline_, {"camera.altitude=5000"}).camera.altitude, 5000.0);
}

TEST_F(OverridesTest, SetsANodeParameterLocatedAtTheOverride) {
  const Pipeline pipeline = parse(pipeline_, {"nodes.imagery.scale=50"});
  const ParameterSet& parameters = pipeline.find("imagery")->parameters;
  EXPECT_DOUBLE_EQ(parameters.real("scale"), 50.0);
  EXPECT_EQ(parameters.where("scale").file, "--set");
  EXPECT_EQ(parameters.where("scale").line, 0);
  EXPECT_EQ(parameters.where("scale").column, 0);
  EXPECT_EQ(parameters.where("scale").node, "imagery");
  EXPECT_EQ(parameters.where("path").file, pipelineFile().string());  // untouched values keep the file
}

TEST_F(OverridesTest, ValueIsReadAsYaml) {
  const Pipeline pipeline = parse(pipeline_, {"nodes.relief={type: source.gdal, path: relief.gtx, kind: height}",
                                              "nodes.frame.surface=[relief, imagery]"});
  EXPECT_EQ(pipeline.find("frame")->inputs.at("surface"), (std::vector<std::string>{"relief", "imagery"}));
  EXPECT_EQ(pipeline.find("relief")->parameters.string("kind"), "height");
}

TEST_F(OverridesTest, AddsAKeyToAMapAnEarlierOverrideMade) {
  const Pipeline pipeline = parse(pipeline_, {"body={name: Moon}", "body.radius=1737400"});
  EXPECT_EQ(pipeline.body.name, "Moon");
  EXPECT_DOUBLE_EQ(pipeline.body.radius, 1737400.0);
}

TEST_F(OverridesTest, AddsAKeyMissingFromAnExistingMap) {
  const Camera camera = parse(pipeline_, {"camera.tilt=30"}).camera;
  EXPECT_DOUBLE_EQ(camera.tilt, 30.0);
  EXPECT_DOUBLE_EQ(camera.altitude, 20000000.0);
}

TEST_F(OverridesTest, LaterOverridesWin) {
  EXPECT_DOUBLE_EQ(parse(pipeline_, {"camera.fov=30", "camera.fov=60"}).camera.fov, 60.0);
}

TEST_F(OverridesTest, ValueEqualsSignsBelongToTheValue) {
  const Pipeline pipeline = parse(pipeline_, {"nodes.frame.title=a=b"});
  EXPECT_EQ(pipeline.find("frame")->parameters.string("title"), "a=b");
}

TEST_F(OverridesTest, WrongValueIsReportedAtTheOverrideAndQuotesIt) {
  const Error error = overrideError("camera.altitude=high");
  EXPECT_EQ(error.problem(), "camera 'altitude' expects a number, got 'high' (set by --set 'camera.altitude=high')");
  EXPECT_EQ(error.where().file, "--set");
  EXPECT_EQ(error.where().line, 0);
  EXPECT_EQ(error.where().column, 0);
  EXPECT_EQ(std::string(error.what()).rfind("--set: error: camera 'altitude'", 0), 0u) << error.what();
}

TEST_F(OverridesTest, NewKeyWithATypoGetsADidYouMean) {
  const Error error = overrideError("nodes.imagery.scael=5");
  EXPECT_EQ(error.problem(),
            "node 'imagery' (source.gdal) has no input or parameter 'scael'; did you mean 'scale'? "
            "(set by --set 'nodes.imagery.scael=5')");
  EXPECT_EQ(error.where().file, "--set");
  EXPECT_EQ(error.where().node, "imagery");
}

TEST_F(OverridesTest, ErrorInsideAnOverriddenListQuotesTheOverride) {
  const Error error = overrideError("nodes.frame.surface=[imagery, clouds]");
  EXPECT_EQ(
      error.problem(),
      "input 'surface' refers to 'clouds', which is not a node (set by --set 'nodes.frame.surface=[imagery, clouds]')");
  EXPECT_EQ(error.where().file, "--set");
  EXPECT_EQ(error.where().node, "frame");
}

TEST_F(OverridesTest, NodeProblemOfAnOverriddenNodeQuotesTheOverride) {
  const Error error = overrideError("nodes.frame={type: output.image, surface: imagery}");
  EXPECT_NE(error.problem().find("is missing its input 'geometry'"), std::string::npos) << error.what();
  EXPECT_NE(error.problem().find("(set by --set 'nodes.frame={type: output.image, surface: imagery}')"),
            std::string::npos)
      << error.what();
  EXPECT_EQ(error.where().file, "--set");
}

TEST_F(OverridesTest, UnknownTopLevelKeyFromAnOverride) {
  const Error error = overrideError("camara={fov: 30}");
  EXPECT_EQ(error.problem(),
            "unknown key 'camara' in the pipeline; did you mean 'camera'? (set by --set 'camara={fov: 30}')");
  EXPECT_EQ(error.where().file, "--set");
}

TEST_F(OverridesTest, SetsAKeyOfASceneSectionThePipelineLeavesOut) {
  const Pipeline pipeline = parse(pipeline_, {"body.radius=1737400", "cache.budget=64"});
  EXPECT_DOUBLE_EQ(pipeline.body.radius, 1737400.0);
  EXPECT_EQ(pipeline.body.name, "Earth") << "the rest of the section keeps its defaults";
  EXPECT_EQ(pipeline.cache.budgetBytes, 64u << 20);
}

TEST_F(OverridesTest, MissingIntermediateKey) {
  const Error error = overrideError("nodes.relief.scale=2");
  EXPECT_EQ(error.problem(), "cannot apply --set 'nodes.relief.scale=2': the pipeline has no 'nodes.relief'");
  EXPECT_EQ(error.where().file, "--set");
  EXPECT_EQ(error.where().line, 0);
  const Error scalar = overrideError("date.day=3");
  EXPECT_EQ(scalar.problem(), "cannot apply --set 'date.day=3': the pipeline has no 'date'")
      << "the date is a value, not a section of keys";
}

TEST_F(OverridesTest, MissingIntermediateKeyDeeperDown) {
  const Error error = overrideError("nodes.relief.scale=2");
  EXPECT_EQ(error.problem(), "cannot apply --set 'nodes.relief.scale=2': the pipeline has no 'nodes.relief'");
  EXPECT_EQ(error.fix(), "add it to the file, or set it whole: --set 'nodes.relief={scale: 2}'");
}

TEST_F(OverridesTest, MisspelledIntermediateKeyGetsADidYouMean) {
  EXPECT_EQ(overrideError("camara.altitude=5").problem(),
            "cannot apply --set 'camara.altitude=5': the pipeline has no 'camara'; did you mean 'camera'?");
  EXPECT_EQ(overrideError("nodes.imagry.scale=2").problem(),
            "cannot apply --set 'nodes.imagry.scale=2': the pipeline has no 'nodes.imagry'; did you mean 'imagery'?");
}

TEST_F(OverridesTest, PathThroughAValueThatIsNotAMap) {
  const Error error = overrideError("nodes.frame.surface.first=imagery");
  EXPECT_EQ(error.problem(),
            "cannot apply --set 'nodes.frame.surface.first=imagery': 'nodes.frame.surface' is not a map, so it has no "
            "keys to set");
  EXPECT_EQ(error.fix(), "set 'nodes.frame.surface' itself: --set 'nodes.frame.surface=VALUE'");
  EXPECT_EQ(error.where().file, "--set");
}

TEST_F(OverridesTest, OverrideWithoutEqualsSign) {
  const Error error = overrideError("camera.altitude");
  EXPECT_EQ(error.problem(), "cannot apply --set 'camera.altitude': it has no '='");
  EXPECT_EQ(error.fix(), "write --set PATH=VALUE, e.g. --set camera.altitude=5000");
  EXPECT_EQ(error.where().file, "--set");
  EXPECT_EQ(error.where().line, 0);
  EXPECT_EQ(error.where().column, 0);
}

TEST_F(OverridesTest, OverrideWithAnEmptyKey) {
  EXPECT_EQ(overrideError("camera..fov=30").problem(), "cannot apply --set 'camera..fov=30': PATH has an empty key");
  EXPECT_EQ(overrideError("=30").problem(), "cannot apply --set '=30': PATH has an empty key");
}

TEST_F(OverridesTest, ValueThatIsNotYaml) {
  const Error error = overrideError("nodes.frame.surface=[imagery");
  EXPECT_EQ(error.problem().rfind("cannot apply --set 'nodes.frame.surface=[imagery': VALUE is not valid YAML: ", 0),
            0u)
      << error.problem();
  EXPECT_NE(error.fix().find("--set 'nodes.frame.surface=[a, b]'"), std::string::npos);
}

TEST_F(OverridesTest, EmptyValueIsNothing) {
  const Error error = overrideError("camera.fov=");
  EXPECT_EQ(error.problem(), "camera 'fov' expects a number, got nothing (set by --set 'camera.fov=')");
}

TEST_F(OverridesTest, OverridesApplyWithLoadPipelineToo) {
  const auto file = directory_.write("pipeline.yaml", pipeline_);
  EXPECT_DOUBLE_EQ(loadPipeline(file, {"camera.tilt=45"}, registry_).camera.tilt, 45.0);
}

}  // namespace
}  // namespace strata::testing
