// End-to-end tests of faults while a pipeline runs (docs/robustness.md): a plugin that fails in any phase
// is named with its node, type and what it was doing, and a GL without the memory the page cache asks
// for gets a smaller cache, not a broken picture.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

class Faults : public StrataCommandTest {
 protected:
  CommandResult renderFailing(const std::string& phase, const std::string& throws = "exception") const {
    writeCheckerboard(file("board.tif"));
    const fs::path pipeline = write("p.yaml",
                                    "strata: 1\nnodes:\n"
                                    "  board: {type: source.gdal, path: board.tif}\n"
                                    "  faulty: {type: composite.faulty, layer: board, fails: " +
                                        phase + ", throws: " + throws +
                                        "}\n"
                                        "  globe: {type: geometry.icosahedral}\n"
                                        "  frame: {type: output.image, geometry: globe, surface: [faulty]}\n");
    return renderTiny(pipeline, STRATA_E2E_PLUGIN_DIR);
  }
};

void expectNamed(const CommandResult& result, const std::string& doing, const std::string& why) {
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "p.yaml:4:3 (node 'faulty')")) << result.err;
  EXPECT_TRUE(contains(result.err, "node 'faulty' (composite.faulty) " + doing + ": " + why)) << result.err;
}

TEST_F(Faults, APluginFailingInAnyPhaseIsNamedWithWhatItWasDoing) {
  const std::pair<std::string, std::string> phases[] = {{"create", "could not be made"},
                                                        {"open", "could not read its data"},
                                                        {"resources", "could not create its GPU resources"},
                                                        {"prepare", "failed to prepare a frame"},
                                                        {"render", "failed to render a frame"}};
  for (const auto& [phase, doing] : phases)
    expectNamed(renderFailing(phase), doing, "composite.faulty fails in " + phase + " as asked");
}

TEST_F(Faults, APluginThrowingWhatIsNoExceptionIsNamedNotACrash) {
  expectNamed(renderFailing("render", "other"), "failed to render a frame",
              "its plugin threw something that is no std::exception");
}

// llvmpipe refuses array textures past about 1 GiB with GL_OUT_OF_MEMORY, as a GPU does past its memory;
// the cache then holds fewer pages, and the frame is the one a modest budget draws. (About 10 s here: the
// GiB llvmpipe does allocate is cleared.)
TEST_F(Faults, AGpuWithoutTheMemoryTheCacheAsksForGetsASmallerCache) {
  writeCheckerboard(file("board.tif"));
  const auto render = [&](const std::string& budget, const std::string& image) {
    const fs::path pipeline = write("p.yaml", "strata: 1\ncache: {budget: " + budget +
                                                  "}\nnodes:\n"
                                                  "  board: {type: source.gdal, path: board.tif}\n"
                                                  "  globe: {type: geometry.icosahedral}\n"
                                                  "  frame: {type: output.image, geometry: globe, surface: [board]}\n");
    return run({"render", pipeline.string(), "--size", "128x72", "-o", file(image).string()});
  };
  const CommandResult asked = render("60000", "asked.png");
  ASSERT_EQ(asked.exitCode, 0) << asked.err;
  EXPECT_TRUE(asked.err.empty() || contains(asked.err, "strata: warning: the GPU has no memory for the page cache"))
      << asked.err;
  EXPECT_FALSE(contains(asked.err, "GL error")) << asked.err;
  ASSERT_EQ(render("256", "modest.png").exitCode, 0);
  EXPECT_EQ(readImage(file("asked.png")).rgba, readImage(file("modest.png")).rgba);
}

}  // namespace
}  // namespace strata::test
