// Path files (format `strata-path: 1`): both forms read, and every mistake is named at its line and column
// with what would fix it.
#include <gtest/gtest.h>

#include <strata/error.hpp>
#include <strata/host/camera_path.hpp>

namespace strata {
namespace {

CameraPath parse(const std::string& text) { return parseCameraPath(text, "path.yaml", Body{}); }

// The error that `text` gives; fails the test when it reads without one.
Error errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return Error(SourceLocation{}, "");
}

void expectError(const std::string& text, int line, int column, const std::string& problemPart) {
  const Error error = errorOf(text);
  EXPECT_EQ(error.where().file, "path.yaml");
  EXPECT_EQ(error.where().line, line) << error.what();
  EXPECT_EQ(error.where().column, column) << error.what();
  EXPECT_NE(error.problem().find(problemPart), std::string::npos) << error.what();
  EXPECT_FALSE(error.fix().empty()) << error.what();
}

TEST(CameraPathFileTest, ReadsKeyframesWithDefaultsForHowTheCameraLooks) {
  const CameraPath path = parse(
      "strata-path: 1\n"
      "keyframes:\n"
      "  - {time: 2, lon: 0, lat: 20, altitude: 2.0e7}\n"
      "  - {time: 12, lon: 10, lat: 46, altitude: 5000, heading: 30, tilt: 70, fov: 30}\n");
  EXPECT_EQ(path.start(), 2.0);
  EXPECT_EQ(path.end(), 12.0);
  const Camera first = path.at(2.0), last = path.at(12.0);
  EXPECT_EQ(first.heading, 0.0);
  EXPECT_EQ(first.tilt, 0.0);
  EXPECT_EQ(first.fov, 45.0);
  EXPECT_NEAR(last.tilt, 70.0, 1e-12);
  EXPECT_NEAR(last.fov, 30.0, 1e-12);
}

TEST(CameraPathFileTest, ReadsAFlight) {
  const CameraPath path = parse(
      "strata-path: 1\n"
      "fly_to:\n"
      "  from: {lon: 10, lat: 46, altitude: 5000}\n"
      "  to: {lon: -70, lat: -33, altitude: 5000}\n"
      "  duration: 20\n"
      "  rho: 2\n");
  EXPECT_EQ(path.end(), 20.0);
  EXPECT_GT(path.at(10.0).altitude, 1.0e6);
}

TEST(CameraPathFileTest, NamesKeyframeTimesThatDoNotIncrease) {
  expectError(
      "strata-path: 1\n"
      "keyframes:\n"
      "  - {time: 5, lon: 0, lat: 20, altitude: 2.0e7}\n"
      "  - {time: 5, lon: 10, lat: 46, altitude: 5000}\n",
      4, 12, "keyframe 2's time, 5 s, is not later than the keyframe before's, 5 s");
}

TEST(CameraPathFileTest, SuggestsTheNearestKeyForAnUnknownOne) {
  expectError(
      "strata-path: 1\n"
      "keyframes:\n"
      "  - {time: 0, lon: 0, lat: 20, altitude: 2.0e7}\n"
      "  - {time: 1, lon: 10, lat: 46, altitdue: 5000}\n",
      4, 33, "unknown key 'altitdue' in keyframe 2; did you mean 'altitude'?");
  expectError("strata-path: 1\nkeyframe: []\n", 2, 1, "did you mean 'keyframes'?");
}

TEST(CameraPathFileTest, NamesAMissingField) {
  expectError(
      "strata-path: 1\n"
      "keyframes:\n"
      "  - {time: 0, lon: 0, altitude: 2.0e7}\n"
      "  - {time: 1, lon: 10, lat: 46, altitude: 5000}\n",
      3, 5, "keyframe 1 has no 'lat'");
  expectError(
      "strata-path: 1\n"
      "keyframes:\n"
      "  - {lon: 0, lat: 0, altitude: 2.0e7}\n"
      "  - {time: 1, lon: 10, lat: 46, altitude: 5000}\n",
      3, 5, "keyframe 1 has no 'time'");
  expectError("strata-path: 1\nfly_to: {from: {lon: 0, lat: 0, altitude: 1e6}, duration: 3}\n", 2, 9,
              "'fly_to' has no 'to'");
  expectError("keyframes: []\n", 1, 1, "no 'strata-path' format version");
  expectError("strata: 1\nnodes: {}\n", 1, 1, "no 'strata-path' format version");  // a pipeline
}

TEST(CameraPathFileTest, NamesValuesOutOfRange) {
  const std::string second = "  - {time: 1, lon: 10, lat: 46, altitude: 5000}\n";
  expectError("strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 91, altitude: 2.0e7}\n" + second, 3, 28,
              "keyframe 1 'lat' must be in [-90, 90] deg");
  expectError("strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 9, altitude: 0}\n" + second, 3, 41,
              "keyframe 1 'altitude' must be > 0 m");
  expectError("strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 9, altitude: 1, tilt: 95}\n" + second, 3, 50,
              "keyframe 1 'tilt'");
  expectError("strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 9, altitude: high}\n" + second, 3, 41,
              "keyframe 1 'altitude' expects a number");
  expectError(
      "strata-path: 1\nfly_to: {from: {lon: 0, lat: 0, altitude: 1e6}, to: {lon: 1, lat: 0, altitude: 1},"
      " duration: -3}\n",
      2, 94, "'fly_to' 'duration' must be > 0 s");
}

TEST(CameraPathFileTest, NamesWhatMakesNoPath) {
  expectError("strata-path: 2\nkeyframes: []\n", 1, 14, "unsupported path format version 2");
  expectError("strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 0, altitude: 1}\n", 3, 3,
              "'keyframes' has 1; a path needs at least two");
  expectError("strata-path: 1\nkeyframes: {time: 0}\n", 2, 12, "'keyframes' must be a list of cameras");
  expectError("strata-path: 1\n", 1, 1, "neither 'keyframes' nor 'fly_to'");
  expectError(
      "strata-path: 1\nkeyframes:\n  - {time: 0, lon: 0, lat: 10, altitude: 1}\n"
      "  - {time: 1, lon: 180, lat: -10, altitude: 1}\n",
      4, 5, "antipodal");
  expectError("strata-path: 1\nkeyframes: [\n", 3, 1, "invalid YAML");
  expectError("", 0, 0, "the path file is empty");
}

TEST(CameraPathFileTest, NamesAFileThatIsNotThere) {
  try {
    readCameraPath("no/such/path.yaml", Body{});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.where().file, "no/such/path.yaml");
    EXPECT_NE(error.problem().find("not found"), std::string::npos);
  }
}

// The sample paths shipped beside the pipelines read.
TEST(CameraPathFileTest, ReadsTheSamplePaths) {
  for (const char* name : {"flyin.yaml", "fly_to.yaml", "earth_flyin.yaml"}) {
    const CameraPath path = readCameraPath(std::string(STRATA_SOURCE_DIR "/pipelines/paths/") + name, Body{});
    EXPECT_GT(path.end(), path.start()) << name;
  }
}

}  // namespace
}  // namespace strata
