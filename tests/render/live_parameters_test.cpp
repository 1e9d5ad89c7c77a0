// Engine::set: a parameter declared live (ParameterDeclaration::live) reaches its node's uniforms for the
// next frame with nothing rebuilt (issue 8: "change the light and the next frame shows it, with no
// re-tiling"), the peel depth and the fusion strength alike; any other change loads the pipeline again,
// keeping the camera; a bad value is refused as --set refuses it and changes nothing.
//
// Nothing rebuilt: the frame comes from the same output node (its address) and a change undone gives the
// first frame back exactly. A change shows: the frames differ by more than 1 level on average (measured on
// llvmpipe: the light moved from the north-west to the south-east, 4.4 levels over the whole frame, the sky
// included; the peel 5 km deep, 10.9; the fusion off, 12.2).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <strata/error.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 96;

// Procedural heights shaded from the north-west, the peel of a second procedural surface beneath them
// 1 km deep, and two procedural colourings fused: each node's live parameters, drawn side by side as
// the frame's three surfaces would blend, so each is sampled over the whole disc.
const char* kPipeline = R"(strata: 1
body: {name: Mars, radius: 3396190}
camera: {lon: 20, lat: 10, altitude: 9.0e6, fov: 45}
nodes:
  heights: {type: source.procedural, kind: height}
  beneath: {type: source.procedural, kind: height, seed: 7}
  paint: {type: source.procedural, kind: color}
  shaded: {type: composite.relief, height: heights, exaggeration: 20, blend: alone}
  stack: {type: composite.layer_peel, layers: [heights, beneath], peel: 0, depth: 1000}
  peeled: {type: composite.peeled_surface, peel: stack, surfaces: [paint, paint]}
  contrast: {type: source.procedural, kind: color, seed: 3}
  fused: {type: composite.chroma_fusion, luminance: contrast, colour: paint, matching: none}
  globe: {type: geometry.icosahedral}
  frame: {type: output.image, geometry: globe, surface: [SURFACE], shading: none}
)";

std::string pipelineShowing(const std::string& surface) {
  std::string text = kPipeline;
  text.replace(text.find("SURFACE"), 7, surface);
  return text;
}

// The mean difference of two frames in 8-bit levels, printed with `what` changed between them.
double meanDifference(const Image& a, const Image& b, const char* what = nullptr) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
  const double mean = sum / double(a.rgba.size());
  if (what) std::printf("%s: frames differ by %.2f levels on average\n", what, mean);
  return mean;
}

class LiveParameters : public ::testing::Test {
 protected:
  Image frame() { return renderFrames(*engine_, engine_->camera(), kSize, kSize, 1); }
  const FrameOutput* output() { return &engine_->render(kSize, kSize); }
  void load(const std::string& surface) { engine_->load(directory_.write("live.yaml", pipelineShowing(surface))); }

  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_ = makeEngine();
};

TEST_F(LiveParameters, TheLightMovesInTheNextFrameWithNothingRebuilt) {
  load("shaded");
  const Image before = frame();
  const FrameOutput* made = output();
  EXPECT_TRUE(engine_->set("nodes.shaded.azimuth=135"));
  const Image after = frame();
  EXPECT_EQ(output(), made) << "the same nodes draw it";
  EXPECT_GT(meanDifference(before, after, "the light to the south-east"), 1.0);
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("azimuth"), 135.0);
  directory_.write("live.yaml", "strata: 1\nnodes: {broken\n");  // a live change reads no file
  EXPECT_TRUE(engine_->set("nodes.shaded.azimuth=315"));
  EXPECT_EQ(meanDifference(before, frame()), 0.0) << "undone, the first frame again";
}

TEST_F(LiveParameters, ThePeelDepthAndTheFusionStrengthAreLive) {
  load("peeled");
  const Image shallow = frame();
  EXPECT_TRUE(engine_->set("nodes.stack.depth=5000"));
  EXPECT_GT(meanDifference(shallow, frame(), "the peel 5 km deep"), 1.0);
  load("fused");
  const Image fused = frame();
  EXPECT_TRUE(engine_->set("nodes.fused.strength=0"));
  EXPECT_GT(meanDifference(fused, frame(), "the fusion off"), 1.0);
}

TEST_F(LiveParameters, OtherChangesLoadThePipelineAgainKeepingTheCamera) {
  load("shaded");
  engine_->camera().altitude = 5.0e6;
  EXPECT_FALSE(engine_->set("nodes.heights.scale=2"));
  EXPECT_EQ(engine_->camera().altitude, 5.0e6) << "the camera the user moved stays";
  EXPECT_EQ(engine_->pipeline().find("heights")->parameters.real("scale"), 2.0);
  EXPECT_FALSE(engine_->set("camera.altitude=7.0e6"));
  EXPECT_EQ(engine_->camera().altitude, 7.0e6) << "a change to the camera moves it";
}

// The viewer loads an edited pipeline file again (Engine::reload), with the overrides given so far.
TEST_F(LiveParameters, AnEditedFileLoadsAgainKeepingTheCameraAndTheOverrides) {
  load("shaded");
  EXPECT_TRUE(engine_->set("nodes.shaded.azimuth=135"));
  engine_->camera().altitude = 5.0e6;
  std::string edited = pipelineShowing("shaded");
  edited.replace(edited.find("exaggeration: 20"), 16, "exaggeration: 30");
  directory_.write("live.yaml", edited);
  engine_->reload();
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("exaggeration"), 30.0);
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("azimuth"), 135.0) << "the override stays";
  EXPECT_EQ(engine_->camera().altitude, 5.0e6);
  directory_.write("live.yaml", "strata: 1\nnodes: {broken\n");
  EXPECT_THROW(engine_->reload(), Error);
  EXPECT_EQ(engine_->pipeline().find("shaded")->parameters.real("exaggeration"), 30.0) << "as it was";
}

TEST_F(LiveParameters, ABadValueIsRefusedAndChangesNothing) {
  load("peeled");
  const Image before = frame();
  try {
    engine_->set("nodes.shaded.azimuth=400");
    ADD_FAILURE() << "400 degrees accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("--set"), std::string::npos) << error.what();
  }
  try {
    engine_->set("nodes.stack.peel=2");
    ADD_FAILURE() << "the floor peeled";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("peel at most 1"), std::string::npos) << error.what();
  }
  EXPECT_EQ(engine_->pipeline().find("stack")->parameters.integer("peel"), 0);
  EXPECT_EQ(meanDifference(before, frame()), 0.0);
}

}  // namespace
}  // namespace strata::test
