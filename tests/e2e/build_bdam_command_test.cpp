// End-to-end tests of `strata build-bdam`: EGM96's geoid (proj-data, a real global raster) built into six face files
// with progress on stderr; face files already there kept unless --overwrite; a raster it cannot use refused with the
// file named and what to do, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "strata_command.hpp"

namespace strata::test {
namespace {

namespace fs = std::filesystem;

const std::string kGeoid = "/usr/share/proj/egm96_15.gtx";
const std::vector<std::string> kFaces = {"face-0.bdam", "face-1.bdam", "face-2.bdam",
                                         "face-3.bdam", "face-4.bdam", "face-5.bdam"};

class BuildBdamCommand : public StrataCommandTest {};

TEST_F(BuildBdamCommand, WritesSixFaceFilesWithProgressOnStderr) {
  const CommandResult result = run({"build-bdam", kGeoid, file("egm").string(), "--level", "3", "--threads", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(namesIn(file("egm")), kFaces) << "and no scratch folder (it is made beside the files) left behind";
  EXPECT_TRUE(contains(result.out, "6 face files")) << result.out;
  EXPECT_TRUE(contains(result.err, "leaves of level 3 (16 steps a side), 2 threads")) << result.err;
  for (const char* level : {"level  3: 48 diamonds", "level  0: 6 diamonds"})
    EXPECT_TRUE(contains(result.err, level)) << result.err;
}

TEST_F(BuildBdamCommand, KeepsFaceFilesThereUnlessToldToOverwrite) {
  fs::create_directories(file("egm"));
  write("egm/face-2.bdam", "the user's");
  const CommandResult refused = run({"build-bdam", kGeoid, file("egm").string(), "--level", "1"});
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_TRUE(contains(refused.err, "face-2.bdam")) << refused.err;
  EXPECT_EQ(readText(file("egm/face-2.bdam")), "the user's");
  EXPECT_EQ(namesIn(file("egm")), std::vector<std::string>{"face-2.bdam"}) << "nothing built before refusing";
  const CommandResult replaced = run({"build-bdam", kGeoid, file("egm").string(), "--level", "1", "--overwrite"});
  ASSERT_EQ(replaced.exitCode, 0) << replaced.err;
  EXPECT_EQ(namesIn(file("egm")), kFaces);
}

TEST_F(BuildBdamCommand, ARasterItCannotUseIsNamedWithWhatToDo) {
  const fs::path text = write("heights.txt", "not a raster");
  const CommandResult unreadable = run({"build-bdam", text.string(), file("out").string()});
  EXPECT_EQ(unreadable.exitCode, 1);
  EXPECT_TRUE(contains(unreadable.err, text.string() + ": cannot be read as a raster")) << unreadable.err;
  EXPECT_TRUE(contains(unreadable.err, "give a height raster GDAL reads")) << unreadable.err;
  EXPECT_FALSE(fs::exists(file("out")));

  const fs::path bare = write("bare.asc",
                              "ncols 4\nnrows 2\nxllcorner -180\nyllcorner -90\ncellsize 90\n"
                              "0 1 2 3\n4 5 6 7\n");
  const CommandResult radiusless = run({"build-bdam", bare.string(), file("out").string()});
  EXPECT_EQ(radiusless.exitCode, 1);
  EXPECT_TRUE(contains(radiusless.err, "no CRS to take the body's radius from")) << radiusless.err;
  EXPECT_TRUE(contains(radiusless.err, "--radius")) << radiusless.err;
  const CommandResult given = run({"build-bdam", bare.string(), file("out").string(), "--radius", "1737400"});
  EXPECT_EQ(given.exitCode, 0) << given.err;
}

}  // namespace
}  // namespace strata::test
