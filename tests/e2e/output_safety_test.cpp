// Nothing a user has is overwritten without asking, nothing a command reads is overwritten at all, no file is
// written through a link, and images take the format their name asks for (docs/robustness.md, "Outputs").
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPipeline =
    "strata: 1\n"
    "nodes:\n"
    "  imagery: {type: source.gdal, path: board.tif}\n"
    "  globe: {type: geometry.icosahedral}\n"
    "  frame: {type: output.image, geometry: globe, surface: [imagery]}\n";

const RasterFileSpec kRaster{"+proj=longlat +R=3396190", {-30.0, 0.1, 0.0, 15.0, 0.0, -0.1}, 600, 300};

class OutputSafety : public StrataCommandTest {
 protected:
  void SetUp() override {
    writeCheckerboard(file("board.tif"));
    pipeline_ = write("scene.yaml", kPipeline);
    board_ = readText(file("board.tif"));
  }
  CommandResult render(const std::string& output, std::vector<std::string> extra = {}) const {
    std::vector<std::string> arguments{"render", pipeline_.string(), "--size", "32x18", "-o", output};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return run(arguments);
  }
  // The pipeline and its raster are as they were.
  void expectInputsKept() const {
    EXPECT_EQ(readText(pipeline_), kPipeline);
    EXPECT_EQ(readText(file("board.tif")), board_);
  }

  fs::path pipeline_;
  std::string board_;
};

TEST_F(OutputSafety, RenderReplacesAnExistingImageOnlyWithOverwrite) {
  const fs::path image = write("frame.png", "a user's file");
  CommandResult result = render(image.string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "-o: error: '" + image.string() + "' exists already")) << result.err;
  EXPECT_TRUE(contains(result.err, "--overwrite")) << result.err;
  EXPECT_EQ(readText(image), "a user's file");
  result = render(image.string(), {"--overwrite"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(readImage(image).width, 32);
  EXPECT_EQ(namesIn(scratch_.path()),
            (std::vector<std::string>{"board.tif", "frame.png", "scene.yaml", "stderr.txt", "stdout.txt"}))
      << "the scratch folder is gone";
}

// The pipeline and its raster (under another spelling too) are never replaced, whatever is asked.
TEST_F(OutputSafety, RenderNeverReplacesWhatItReads) {
  CommandResult result = render(pipeline_.string(), {"--overwrite"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "cannot write an image named '.yaml'")) << result.err;
  result = render((scratch_.path() / "." / "board.tif").string(), {"--overwrite"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "-o: error: '" + (scratch_.path() / "." / "board.tif").string() + "' is '" +
                                       file("board.tif").string() +
                                       "', a file this work reads; it is never overwritten"))
      << result.err;
  expectInputsKept();
}

TEST_F(OutputSafety, RenderWritesNothingThroughALink) {
  fs::create_symlink(file("elsewhere.png"), file("dangling.png"));
  fs::create_symlink(file("board.tif"), file("board-link.tif"));
  for (const char* name : {"dangling.png", "board-link.tif"}) {
    const CommandResult result = render(file(name).string(), {"--overwrite"});
    EXPECT_EQ(result.exitCode, 1) << name;
    EXPECT_TRUE(contains(result.err, "is a symbolic link; Strata writes no file through a link")) << result.err;
  }
  EXPECT_FALSE(fs::exists(file("elsewhere.png")));
  expectInputsKept();
}

TEST_F(OutputSafety, RenderTakesTheFormatFromTheExtension) {
  ASSERT_EQ(render(file("frame.TIF").string()).exitCode, 0);
  std::unique_ptr<GDALDataset> tiff(GDALDataset::Open(file("frame.TIF").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(tiff);
  EXPECT_STREQ(tiff->GetDriver()->GetDescription(), "GTiff");
  EXPECT_EQ(tiff->GetRasterCount(), 4);
  for (const char* name : {"frame.jpg", "frame.exr", "frame"}) {
    const CommandResult result = render(file(name).string());
    EXPECT_EQ(result.exitCode, 1) << name;
    EXPECT_TRUE(contains(result.err, "cannot write an image named")) << result.err;
    EXPECT_TRUE(contains(result.err, "name the file .png or .tif")) << result.err;
    EXPECT_FALSE(fs::exists(file(name)));
  }
}

// Every frame of a sequence is checked before the first is drawn: one existing frame stops the whole run.
TEST_F(OutputSafety, ASequenceStopsBeforeItsFirstFrameOnAnExistingOne) {
  fs::create_directory(file("seq"));
  write("seq/f_0002.png", "a user's file");
  const CommandResult result = run({"render", "pipelines/procedural.yaml", "--path", "pipelines/paths/flyin.yaml",
                                    "--frames", "3", "--size", "32x18", "-o", file("seq/f_%04d.png").string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "f_0002.png' exists already")) << result.err;
  EXPECT_EQ(namesIn(file("seq")), std::vector<std::string>{"f_0002.png"});
}

TEST_F(OutputSafety, BenchNeverReplacesItsPipelineOrPath) {
  const fs::path path = write("path.yaml",
                              "strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 0, altitude: 2.0e7}\n"
                              "  - {time: 1, lon: 10, lat: 0, altitude: 2.0e7}\n");
  for (const std::vector<std::string>& outputs :
       {std::vector<std::string>{"-o", pipeline_.string()}, {"--plot", pipeline_.string()}, {"-o", path.string()}}) {
    std::vector<std::string> arguments{"bench", pipeline_.string(), "--path", path.string(), "--frames",
                                       "2",     "--size",           "16x16",  "--overwrite"};
    arguments.insert(arguments.end(), outputs.begin(), outputs.end());
    const CommandResult result = run(arguments);
    EXPECT_EQ(result.exitCode, 1) << outputs[1];
    EXPECT_TRUE(contains(result.err, "a file this work reads; it is never overwritten")) << result.err;
  }
  expectInputsKept();
  EXPECT_TRUE(contains(readText(path), "strata-path: 1"));
}

TEST_F(OutputSafety, BenchReplacesAnExistingTableOnlyWithOverwrite) {
  const fs::path path = write("path.yaml",
                              "strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 0, altitude: 2.0e7}\n"
                              "  - {time: 1, lon: 10, lat: 0, altitude: 2.0e7}\n");
  const fs::path table = write("times.csv", "a user's file");
  const std::vector<std::string> arguments{"bench", pipeline_.string(), "--path", path.string(), "--frames",
                                           "2",     "--size",           "16x16",  "-o",          table.string()};
  CommandResult result = run(arguments);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "times.csv' exists already")) << result.err;
  EXPECT_EQ(readText(table), "a user's file");
  std::vector<std::string> overwriting = arguments;
  overwriting.push_back("--overwrite");
  result = run(overwriting);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(readText(table), "frame,seconds")) << readText(table);
  EXPECT_TRUE(contains(readText(file("times.svg")), "<svg"));
}

// Identity by file, not by spelling: the input under another name, a VRT's source, and a link.
TEST_F(OutputSafety, TileNeverReplacesItsInputWhateverItIsCalled) {
  writeRasterFile(file("same.tif"), kRaster);
  const std::string original = readText(file("same.tif"));
  write("wrap.vrt",
        "<VRTDataset rasterXSize=\"600\" rasterYSize=\"300\"><VRTRasterBand dataType=\"Float32\" band=\"1\">"
        "<SimpleSource><SourceFilename relativeToVRT=\"1\">same.tif</SourceFilename><SourceBand>1</SourceBand>"
        "</SimpleSource></VRTRasterBand></VRTDataset>");
  for (const auto& [input, output] : {std::pair{file("same.tif"), scratch_.path() / "." / "same.tif"},
                                      std::pair{file("wrap.vrt"), file("same.tif")}}) {
    const CommandResult result = run({"tile", input.string(), output.string(), "--overwrite"});
    EXPECT_EQ(result.exitCode, 1) << input;
    EXPECT_TRUE(contains(result.err, "a file this work reads; it is never overwritten")) << result.err;
  }
  EXPECT_EQ(readText(file("same.tif")), original);
  fs::create_symlink(file("elsewhere.tif"), file("dangling.tif"));
  const CommandResult result = run({"tile", file("same.tif").string(), file("dangling.tif").string(), "--overwrite"});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "is a symbolic link")) << result.err;
  EXPECT_FALSE(fs::exists(file("elsewhere.tif")));
}

}  // namespace
}  // namespace strata::test
