// The viewer under faults (docs/robustness.md): a pipeline file edited into one that does not load, a node
// that throws while rendering, and a raster cut short while it is shown. Each is said in the panel (and on
// stderr) while the window goes on; none ends the viewer.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include <strata/host/engine.hpp>
#include <strata/viewer/viewer.hpp>

#include "shared_window.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

const char* kGlobe =
    "strata: 1\ncamera: {lon: 20, lat: 10, altitude: 1.2e7}\nnodes:\n"
    "  colours: {type: source.procedural, kind: color}\n"
    "  globe: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: globe, surface: [colours]}\n";

const char* kFailingGlobe =
    "strata: 1\ncamera: {lon: 20, lat: 10, altitude: 1.2e7}\nnodes:\n"
    "  colours: {type: source.procedural, kind: color}\n"
    "  faulty: {type: composite.faulty, layer: colours, fails: render}\n"
    "  globe: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: globe, surface: [faulty]}\n";

class ViewerFaults : public ::testing::Test {
 protected:
  void open(const std::string& pipeline) {
    EngineOptions options;
    options.pluginDirectories = {STRATA_TEST_PLUGIN_DIR, STRATA_FAULTY_PLUGIN_DIR};
    engine_ = std::make_unique<Engine>(options);
    engine_->load(directory_.write("p.yaml", pipeline));
    viewer_ = std::make_unique<viewer::Viewer>(window_, *engine_);
  }
  // Rewrites the pipeline as an editor would, a second later than it was (the watcher compares times).
  void edit(const std::string& pipeline) {
    const fs::path file = directory_.path() / "p.yaml";
    const auto before = fs::last_write_time(file);
    directory_.write("p.yaml", pipeline);
    fs::last_write_time(file, before + std::chrono::seconds(1));
  }

  GlfwWindow& window_ = sharedWindow();
  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<viewer::Viewer> viewer_;
};

TEST_F(ViewerFaults, AnEditThatDoesNotLoadIsSaidAndThePipelineBeforeItStays) {
  open(kGlobe);
  ASSERT_NE(viewer_->frame(), nullptr);
  edit("strata: 1\nnodes:\n  globe: {type: geometry.icosahedral\n");
  EXPECT_NE(viewer_->frame(), nullptr) << "the pipeline before the edit still draws";
  EXPECT_NE(viewer_->problem().find("p.yaml:"), std::string::npos) << viewer_->problem();
  edit(kGlobe);
  EXPECT_NE(viewer_->frame(), nullptr);
  EXPECT_EQ(viewer_->problem(), "");
}

TEST_F(ViewerFaults, ANodeThatThrowsWhileRenderingIsSaidAndTheViewerGoesOn) {
  open(kFailingGlobe);
  EXPECT_EQ(viewer_->frame(), nullptr);
  EXPECT_NE(viewer_->problem().find("node 'faulty' (composite.faulty) failed to render a frame"), std::string::npos)
      << viewer_->problem();
  EXPECT_EQ(viewer_->frame(), nullptr) << "not tried again until the file changes";
  edit(kGlobe);
  EXPECT_NE(viewer_->frame(), nullptr);
  EXPECT_EQ(viewer_->problem(), "");
}

// The raster is cut to half its length in place once the pipeline has opened it: the pages of the lost
// half are reported (PageCacheStatistics::failed), and masked or stood in for by coarser ones.
TEST_F(ViewerFaults, ARasterCutShortWhileShownCostsDetailNotTheViewer) {
  writeColourRaster(directory_.path() / "board.tif", 2048, 1024, {-180.0, -90.0, 180.0, 90.0},
                    [](int column, int row) { return cellColour(column / 256, row / 256); });
  open(
      "strata: 1\ncamera: {lon: 20, lat: -60, altitude: 3.0e6}\nnodes:\n"
      "  board: {type: source.gdal, path: board.tif}\n"
      "  globe: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: globe, surface: [board]}\n");
  const fs::path board = directory_.path() / "board.tif";
  fs::resize_file(board, fs::file_size(board) / 2);
  for (int i = 0; i < 40 && engine_->pageCacheStatistics().failed == 0; ++i) ASSERT_NE(viewer_->frame(), nullptr);
  EXPECT_GT(engine_->pageCacheStatistics().failed, 0u);
  EXPECT_NE(viewer_->frame(), nullptr);
}

}  // namespace
}  // namespace strata::test
