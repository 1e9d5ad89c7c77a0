// End-to-end tests of what `strata render` says about compositors it cannot build: each ends in exit code 1
// with the pipeline's line and column and a fix, before anything is drawn.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "strata_command.hpp"

namespace strata::test {
namespace {

class CompositorErrors : public StrataCommandTest {
 protected:
  // A pipeline of a procedural colour layer `a`, the nodes given (among them the compositor `c`), drawn on a
  // bare globe.
  CommandResult renderWith(const std::string& nodes) const {
    return renderTiny(write("p.yaml",
                            "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
                            "  a: {type: source.procedural, kind: color}\n" +
                                nodes +
                                "  g: {type: geometry.icosahedral}\n"
                                "  f: {type: output.image, geometry: g, surface: [c]}\n"));
  }
};

TEST_F(CompositorErrors, ProjectionQualityNeedsLayers) {
  const CommandResult result = renderWith("  c: {type: composite.projection_quality, layers: []}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:5:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "missing its input 'layers'")) << result.err;
}

TEST_F(CompositorErrors, ProjectionQualityRefusesLayersOfDifferentKinds) {
  const CommandResult result = renderWith(
      "  h: {type: source.procedural, kind: height}\n"
      "  c: {type: composite.projection_quality, layers: [a, h]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "different kinds (color and height)")) << result.err;
  EXPECT_TRUE(contains(result.err, "fix:")) << result.err;
}

// Procedural layers have no projection; a raster's is known only once it is placed, after the node is made.
TEST_F(CompositorErrors, ProjectionQualityByLatitudeNeedsLayersThatSampleTheEquatorOrAPole) {
  const std::string data = std::string(STRATA_SOURCE_DIR) + "/build/test-data/";
  for (const auto& [inputs, named] : {std::pair<std::string, std::string>{"[a]", "layer 1"}, {"[gl, hp]", "layer 2"}}) {
    const CommandResult result = renderWith("  gl: {type: source.gdal, path: " + data +
                                            "global-color.tif}\n"
                                            "  hp: {type: source.gdal, path: " +
                                            data +
                                            "healpix-color.tif}\n"
                                            "  c: {type: composite.projection_quality, layers: " +
                                            inputs + ", method: latitude}\n");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(contains(result.err, "p.yaml:7:")) << "at `method`: " << result.err;
    EXPECT_TRUE(contains(result.err, "(node 'c')")) << result.err;
    EXPECT_TRUE(contains(result.err, "weighs each layer by the region its projection samples best")) << result.err;
    EXPECT_TRUE(contains(result.err, named + " of its `layers`")) << result.err;
    EXPECT_TRUE(contains(result.err, "use method: isotropy")) << result.err;
  }
}

TEST_F(CompositorErrors, ProjectionQualityRefusesABandTurnedOver) {
  const CommandResult result = renderWith("  c: {type: composite.projection_quality, layers: [a], band: [70, 50]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:5:")) << "at `band`: " << result.err;
  EXPECT_TRUE(contains(result.err, "0 < inner < outer < 90")) << result.err;
}

TEST_F(CompositorErrors, OverlayMaskCannotFeatherAnOverlayWithoutTexels) {
  const CommandResult result = renderWith(
      "  o: {type: source.procedural, kind: color}\n"
      "  c: {type: composite.overlay_mask, base: a, overlay: o, feather: 3}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:")) << "at `feather`: " << result.err;
  EXPECT_TRUE(contains(result.err, "feather: 0 for a hard edge")) << result.err;
}

TEST_F(CompositorErrors, OverlayMaskRefusesAnOverlayOfAnotherKind) {
  const CommandResult result = renderWith(
      "  h: {type: source.procedural, kind: height}\n"
      "  c: {type: composite.overlay_mask, base: a, overlay: h}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "the overlay is a height layer, the base a color layer")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendWantsOneDatePerStep) {
  const CommandResult result = renderWith(
      "  b: {type: source.procedural, kind: color}\n"
      "  c: {type: composite.temporal_blend, steps: [a, b], dates: [2004-01-15]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:")) << "at `dates`: " << result.err;
  EXPECT_TRUE(contains(result.err, "1 dates for 2 steps")) << result.err;
  EXPECT_TRUE(contains(result.err, "give one date per step")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendWantsItsDatesInOrder) {
  const CommandResult result = renderWith(
      "  b: {type: source.procedural, kind: color}\n"
      "  c: {type: composite.temporal_blend, steps: [a, b], dates: [2004-02-15, 2004-01-15]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "not in increasing order: 2004-01-15 follows 2004-02-15")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendNeedsTheScenesDate) {
  const CommandResult result = renderWith("  c: {type: composite.temporal_blend, steps: [a], dates: [2004-01-15]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:5:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "add `date: 2004-06-15`")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendTakesItsStepsOneWay) {
  const CommandResult result =
      renderWith("  c: {type: composite.temporal_blend, steps: [a], dates: [2004-01-15], files: 'm%m.tif'}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "the steps are given twice")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendFilesThatMatchNothing) {
  const CommandResult result = renderWith("  c: {type: composite.temporal_blend, files: 'month-%m.tif'}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:5:")) << "at `files`: " << result.err;
  EXPECT_TRUE(contains(result.err, "matches 'month-%m.tif'")) << result.err;
}

TEST_F(CompositorErrors, TemporalBlendDateThatIsNoDay) {
  const CommandResult result = renderWith("  c: {type: composite.temporal_blend, steps: [a], dates: [2004-13-15]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:5:59")) << "at the date itself: " << result.err;
  EXPECT_TRUE(contains(result.err, "element 1 of parameter 'dates' is '2004-13-15', which is not a date"))
      << result.err;
}

TEST_F(CompositorErrors, OverlayMaskRefusesAMaskThatIsTheOverlay) {
  const CommandResult result = renderWith(
      "  o: {type: source.procedural, kind: color}\n"
      "  c: {type: composite.overlay_mask, base: a, overlay: o, mask: o}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "the mask is also the overlay")) << result.err;
  EXPECT_TRUE(contains(result.err, "a node of its own")) << result.err;
}

// A stack of two procedural height layers `h` and `k` peeled by `s`, coloured by `c` from `a`.
const std::string kStack =
    "  h: {type: source.procedural, kind: height}\n"
    "  k: {type: source.procedural, kind: height, seed: 7}\n";

TEST_F(CompositorErrors, LayerPeelNeedsTwoLayers) {
  const CommandResult result = renderWith(kStack +
                                          "  s: {type: composite.layer_peel, layers: [h]}\n"
                                          "  c: {type: composite.peeled_surface, peel: s, surfaces: [a]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:7:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "a stack needs two layers or more, and has 1")) << result.err;
}

TEST_F(CompositorErrors, LayerPeelCannotPeelTheFloor) {
  const CommandResult result = renderWith(kStack +
                                          "  s: {type: composite.layer_peel, layers: [h, k], peel: 2}\n"
                                          "  c: {type: composite.peeled_surface, peel: s, surfaces: [a, a]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:7:")) << "at `peel`: " << result.err;
  EXPECT_TRUE(contains(result.err, "peel 2 takes away more layers than lie above the floor (1)")) << result.err;
  EXPECT_TRUE(contains(result.err, "peel at most 1")) << result.err;
}

TEST_F(CompositorErrors, LayerPeelRefusesABoxTurnedOver) {
  const CommandResult result = renderWith(kStack +
                                          "  s: {type: composite.layer_peel, layers: [h, k], cut: box,\n"
                                          "      box: [10, 0, -10, 5]}\n"
                                          "  c: {type: composite.peeled_surface, peel: s, surfaces: [a, a]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:8:")) << "at `box`: " << result.err;
  EXPECT_TRUE(contains(result.err, "[170, -10, 190, 10]")) << result.err;
}

TEST_F(CompositorErrors, PeeledSurfaceWantsOneSurfacePerLayer) {
  const CommandResult result = renderWith(kStack +
                                          "  s: {type: composite.layer_peel, layers: [h, k]}\n"
                                          "  c: {type: composite.peeled_surface, peel: s, surfaces: [a]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:8:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "it has 1 surfaces for a stack of 2 layers")) << result.err;
}

TEST_F(CompositorErrors, PeeledSurfaceColoursALayerPeel) {
  const CommandResult result =
      renderWith(kStack + "  c: {type: composite.peeled_surface, peel: h, surfaces: [a, a]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:7:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "its peel is not a composite.layer_peel node")) << result.err;
}

TEST_F(CompositorErrors, PeeledSurfaceWantsAFaceColourPerLayer) {
  const CommandResult result = renderWith(kStack +
                                          "  s: {type: composite.layer_peel, layers: [h, k]}\n"
                                          "  c: {type: composite.peeled_surface, peel: s, surfaces: [a, a],\n"
                                          "      faces: [1, 0, 0]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:9:")) << "at `faces`: " << result.err;
  EXPECT_TRUE(contains(result.err, "faces has 3 numbers, not three for each of the stack's 2 layers")) << result.err;
}

TEST_F(CompositorErrors, TranslucentGeometriesWantOneSurfaceEach) {
  const CommandResult result = renderTiny(write("p.yaml",
                                                "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
                                                "  a: {type: source.procedural, kind: color}\n"
                                                "  g: {type: geometry.icosahedral}\n"
                                                "  u: {type: geometry.icosahedral}\n"
                                                "  f: {type: output.image, geometry: g, surface: [a],\n"
                                                "      translucent: [u], translucent_surface: [a, a]}\n"));
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:7:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "1 translucent geometries have 2 translucent_surface layers")) << result.err;
}

}  // namespace
}  // namespace strata::test
