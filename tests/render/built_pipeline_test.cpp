// Engine::load(PipelineBuilder): a host builds its pipeline in code (issue 11, "loads a pipeline from a
// file or builds one in code") and the engine renders it as it renders the same document from a file;
// set() and reload() build it again from the engine's own copy of the builder.
//
// Frames are compared exactly: the same nodes with the same parameters on the same context draw the same
// pixels (llvmpipe rasterises deterministically), so any difference means the pipelines differ.
#include <gtest/gtest.h>

#include <strata/error.hpp>
#include <strata/host/pipeline_builder.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 64;

// Procedural heights shaded from the north-west, drawn on an icosahedral Mars.
PipelineBuilder shadedMars(const std::filesystem::path& directory) {
  PipelineBuilder pipeline("shaded-mars", directory);
  pipeline.set("body.name", "Mars").set("body.radius", 3396190.0);
  pipeline.set("camera.lon", 20).set("camera.lat", 10).set("camera.altitude", 9.0e6);
  pipeline.node("heights", "source.procedural", {{"kind", "height"}});
  pipeline.node("shaded", "composite.relief", {{"height", "heights"}, {"exaggeration", 20}, {"blend", "alone"}});
  pipeline.node("globe", "geometry.icosahedral");
  pipeline.node("frame", "output.image",
                {{"geometry", "globe"}, {"surface", std::vector<std::string>{"shaded"}}, {"shading", "none"}});
  return pipeline;
}

class BuiltPipeline : public ::testing::Test {
 protected:
  Image frame() { return renderFrames(*engine_, engine_->camera(), kSize, kSize, 1); }

  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_ = makeEngine();
};

TEST_F(BuiltPipeline, RendersAsTheSameDocumentInAFile) {
  const PipelineBuilder builder = shadedMars(directory_.path());
  engine_->load(builder);
  EXPECT_TRUE(engine_->pipeline().file.empty());
  EXPECT_EQ(engine_->pipeline().body.name, "Mars");
  const Image built = frame();
  EXPECT_TRUE(covered(built, kSize / 2, kSize / 2)) << "the planet is drawn";
  engine_->load(directory_.write("shaded-mars.yaml", builder.yaml()));
  EXPECT_TRUE(built.rgba == frame().rgba) << "the file's frame differs; the document:\n" << builder.yaml();
}

TEST_F(BuiltPipeline, SetBuildsTheEnginesCopyAgainKeepingTheCamera) {
  PipelineBuilder builder = shadedMars(directory_.path());
  engine_->load(builder);
  const Image first = frame();
  builder.set("nodes.shaded.exaggeration", 5);  // the host's builder, not the engine's copy
  engine_->camera().altitude = 8.0e6;
  EXPECT_FALSE(engine_->set("nodes.heights.scale=2")) << "not live: the pipeline is built again";
  EXPECT_EQ(engine_->pipeline().find("heights")->parameters.real("scale"), 2.0);
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("exaggeration"), 20.0);
  EXPECT_EQ(engine_->camera().altitude, 8.0e6) << "the camera the host moved stays";
  EXPECT_TRUE(engine_->set("nodes.shaded.azimuth=135"));
  EXPECT_FALSE(frame().rgba == first.rgba) << "the heights and the light changed";
}

TEST_F(BuiltPipeline, ReloadBuildsAgainWithTheOverridesSoFar) {
  engine_->load(shadedMars(directory_.path()), {"nodes.shaded.exaggeration=30"});
  EXPECT_TRUE(engine_->set("nodes.shaded.azimuth=135"));
  const Image before = frame();
  engine_->reload();
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("exaggeration"), 30.0);
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("azimuth"), 135.0);
  EXPECT_TRUE(frame().rgba == before.rgba) << "the same pipeline, the same frame";
}

TEST_F(BuiltPipeline, ABadBuilderIsRefusedAndTheLoadedPipelineStays) {
  engine_->load(shadedMars(directory_.path()));
  PipelineBuilder broken = shadedMars(directory_.path());
  broken.set("nodes.shaded.height", "hieghts");
  try {
    engine_->load(broken);
    ADD_FAILURE() << "a pipeline naming a missing node loaded";
  } catch (const Error& error) {
    EXPECT_EQ(error.where().str(), "shaded-mars (node 'shaded')");
    EXPECT_NE(error.problem().find("heights"), std::string::npos) << error.what() << " (no did-you-mean)";
  }
  EXPECT_EQ(engine_->pipeline().find("shaded")->inputs.at("height"), std::vector<std::string>{"heights"});
  EXPECT_THROW(engine_->set("nodes.heights.scale=-1"), Error);
  EXPECT_EQ(engine_->pipeline().find("heights")->parameters.real("scale"), 1.0) << "as it was";
}

}  // namespace
}  // namespace strata::test
