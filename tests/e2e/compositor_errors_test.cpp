// End-to-end tests of what `strata render` says about compositors it cannot build: each ends in exit code 1
// with the pipeline's line and column and a fix, before anything is drawn.
#include <gtest/gtest.h>

#include <string>

#include "strata_command.hpp"

namespace strata::test {
namespace {

class CompositorErrors : public StrataCommandTest {
 protected:
  // A pipeline of a procedural colour layer `a`, the nodes given (among them the compositor `c`), drawn on a
  // bare globe.
  CommandResult renderWith(const std::string& nodes) const {
    return renderTiny(write("p.yaml", "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
                                      "  a: {type: source.procedural, kind: color}\n" + nodes +
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
  const CommandResult result = renderWith("  h: {type: source.procedural, kind: height}\n"
                                          "  c: {type: composite.projection_quality, layers: [a, h]}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "different kinds (color and height)")) << result.err;
  EXPECT_TRUE(contains(result.err, "fix:")) << result.err;
}

TEST_F(CompositorErrors, OverlayMaskCannotFeatherAnOverlayWithoutTexels) {
  const CommandResult result = renderWith("  o: {type: source.procedural, kind: color}\n"
                                          "  c: {type: composite.overlay_mask, base: a, overlay: o, feather: 3}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:")) << "at `feather`: " << result.err;
  EXPECT_TRUE(contains(result.err, "feather: 0 for a hard edge")) << result.err;
}

TEST_F(CompositorErrors, OverlayMaskRefusesAnOverlayOfAnotherKind) {
  const CommandResult result = renderWith("  h: {type: source.procedural, kind: height}\n"
                                          "  c: {type: composite.overlay_mask, base: a, overlay: h}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "the overlay is a height layer, the base a color layer")) << result.err;
}

TEST_F(CompositorErrors, OverlayMaskRefusesAMaskThatIsTheOverlay) {
  const CommandResult result = renderWith("  o: {type: source.procedural, kind: color}\n"
                                          "  c: {type: composite.overlay_mask, base: a, overlay: o, mask: o}\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:6:3")) << result.err;
  EXPECT_TRUE(contains(result.err, "the mask is also the overlay")) << result.err;
  EXPECT_TRUE(contains(result.err, "a node of its own")) << result.err;
}

}  // namespace
}  // namespace strata::test
