// `strata render --path`: a flight along a camera path renders a frame sequence that is the same, byte for
// byte, on every run (each frame waits for every page it needs), and a video when ffmpeg is installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "strata_command.hpp"

namespace {

namespace fs = std::filesystem;

using strata::test::CommandResult;
using strata::test::contains;
using strata::test::readText;
using strata::test::StrataCommandTest;

constexpr int kFrames = 3;

bool ffmpegOnPath() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

class CameraPathCommandTest : public StrataCommandTest {
 protected:
  // kFrames small frames of a sample path, to `output`: by default the fly-in over the procedural planet.
  CommandResult renderFlyIn(const std::string& output, const std::string& pipeline = "pipelines/procedural.yaml",
                            const std::string& path = "pipelines/paths/flyin.yaml") const {
    return run(
        {"render", pipeline, "--path", path, "--frames", std::to_string(kFrames), "--size", "96x54", "-o", output});
  }
};

// The demo's Earth imagery is paged: coming closer, each frame wants finer pages than the coarsest level
// loaded with the pipeline, and waits for them, so the frames do not depend on the loader threads' timing.
TEST_F(CameraPathCommandTest, RendersTheSameFramesOnEveryRun) {
  const auto render = [&](const std::string& directory) {
    return renderFlyIn(file(directory + "/frame_%05d.png").string(), "pipelines/demo.yaml",
                       "pipelines/paths/earth_flyin.yaml");
  };
  const CommandResult first = render("first");
  ASSERT_EQ(first.exitCode, 0) << first.err;
  EXPECT_TRUE(contains(first.out, "wrote 3 frames")) << first.out;
  const CommandResult second = render("second");
  ASSERT_EQ(second.exitCode, 0) << second.err;
  for (int frame = 0; frame < kFrames; ++frame) {
    const std::string name = "/frame_0000" + std::to_string(frame) + ".png";
    const std::string bytes = readText(file("first" + name));
    ASSERT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, readText(file("second" + name))) << name << " differs between two runs";
  }
  // The camera moves: the wide view of the Earth and the close-up differ.
  EXPECT_NE(readText(file("first/frame_00000.png")), readText(file("first/frame_00002.png")));
}

// ffmpeg encodes the frames when it is installed; without it the command stops before rendering and says
// how to install it.
TEST_F(CameraPathCommandTest, EncodesAVideoOrSaysHowToGetFfmpeg) {
  const CommandResult result = renderFlyIn(file("flyin.mp4").string());
  if (ffmpegOnPath()) {
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_GT(fs::file_size(file("flyin.mp4")), 0u);
    // The frames were encoded from a fresh scratch folder, gone with them: none of an earlier run's.
    for (const auto& entry : fs::directory_iterator(scratch_.path()))
      EXPECT_TRUE(entry.path().filename() == "flyin.mp4" || entry.path().extension() == ".txt") << entry.path();
  } else {
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(contains(result.err, "-o: error: a video needs ffmpeg")) << result.err;
    EXPECT_TRUE(contains(result.err, "apt-get install ffmpeg")) << result.err;
    EXPECT_FALSE(fs::exists(file("flyin_frames")));
  }
}

TEST_F(CameraPathCommandTest, NamesAMistakeInThePathFileAtItsLine) {
  const fs::path path = write("bad.yaml",
                              "strata-path: 1\n"
                              "keyframes:\n"
                              "  - {time: 0, lon: 0, lat: 20, altitude: 2.0e7}\n"
                              "  - {time: 1, lon: 10, lat: 46, altitud: 5000}\n");
  const CommandResult result =
      run({"render", "pipelines/procedural.yaml", "--path", path.string(), "-o", file("f_%02d.png").string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, path.string() + ":4:33: error: unknown key 'altitud'")) << result.err;
  EXPECT_TRUE(contains(result.err, "did you mean 'altitude'")) << result.err;
}

TEST_F(CameraPathCommandTest, RefusesPathWithDatesAndTooFewFrames) {
  const CommandResult both = run({"render", "pipelines/procedural.yaml", "--path", "pipelines/paths/flyin.yaml",
                                  "--dates", "2004-01-01/2004-02-01", "-o", file("f_%02d.png").string()});
  EXPECT_EQ(both.exitCode, 1);
  EXPECT_TRUE(contains(both.err, "--dates")) << both.err;
  const CommandResult alone = run({"render", "pipelines/procedural.yaml", "--frames", "3"});
  EXPECT_EQ(alone.exitCode, 1);
  EXPECT_TRUE(contains(alone.err, "--frames: error:")) << alone.err;
  const CommandResult one = run({"render", "pipelines/procedural.yaml", "--path", "pipelines/paths/flyin.yaml",
                                 "--frames", "1", "-o", file("f_%02d.png").string()});
  EXPECT_EQ(one.exitCode, 1);
  EXPECT_TRUE(contains(one.err, "--frames: error: a camera path takes at least 2 frames")) << one.err;
  EXPECT_TRUE(contains(one.err, "--frames 361")) << one.err;  // 30 a second of the 12 s path, and one
}

}  // namespace
