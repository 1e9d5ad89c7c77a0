// `strata tile` interrupted by SIGINT at several moments leaves either the finished pyramid or nothing, and
// no temporary file (GDAL's *.ovr.tmp and *.warped.tif.tmp, the HEALPix strip) (docs/robustness.md, "Outputs").
#include <fcntl.h>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "strata_command.hpp"
#include "test_rasters.hpp"

extern char** environ;

namespace strata::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// One way of writing a pyramid, on an input large enough that it takes about a second on two cores, so that
// signals land inside its phases: the north of the globe, which reprojects to polar stereographic too.
struct WayOfWriting {
  const char* name;
  std::vector<std::string> options;
  double texelDegrees;
};

void PrintTo(const WayOfWriting& way, std::ostream* out) { *out << way.name; }

RasterFileSpec inputOf(const WayOfWriting& way) {
  const double d = way.texelDegrees;
  return {"+proj=longlat +R=3396190", {-180.0, d, 0.0, 90.0, 0.0, -d}, int(360.0 / d), int(60.0 / d)};
}

// A started strata, its environment as StrataCommandTest gives it (no STRATA_PLUGIN_PATH) and SIGINT at its
// default action whatever the test runner's is, as in a terminal.
pid_t startStrata(const std::vector<std::string>& arguments) {
  std::vector<std::string> all{STRATA_EXECUTABLE};
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& argument : all) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::vector<char*> environment;
  for (char** variable = environ; *variable; ++variable)
    if (std::string(*variable).rfind("STRATA_PLUGIN_PATH=", 0) != 0) environment.push_back(*variable);
  environment.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t signals;
  sigemptyset(&signals);
  posix_spawnattr_setsigmask(&attributes, &signals);
  sigaddset(&signals, SIGINT);
  posix_spawnattr_setsigdefault(&attributes, &signals);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t child = -1;
  const int status = posix_spawn(&child, argv[0], &files, &attributes, argv.data(), environment.data());
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attributes);
  return status == 0 ? child : -1;
}

int waitFor(pid_t child) {
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

// What identifies a finished pyramid: its size, overviews and the checksum of its full resolution.
std::string fingerprint(const fs::path& file) {
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset) return "unreadable";
  GDALRasterBand& band = *dataset->GetRasterBand(1);
  return std::to_string(dataset->GetRasterXSize()) + "x" + std::to_string(dataset->GetRasterYSize()) + ", " +
         std::to_string(band.GetOverviewCount()) + " overviews, checksum " +
         std::to_string(GDALChecksumImage(GDALRasterBand::ToHandle(&band), 0, 0, band.GetXSize(), band.GetYSize()));
}

class InterruptedTile : public StrataCommandTest, public ::testing::WithParamInterface<WayOfWriting> {};

TEST_P(InterruptedTile, LeavesTheFinishedFileOrNothing) {
  fs::create_directory(file("work"));
  writeRasterFile(file("work/in.tif"), inputOf(GetParam()));
  const fs::path output = file("work/out.tif");
  std::vector<std::string> arguments{"tile", file("work/in.tif").string(), output.string()};
  arguments.insert(arguments.end(), GetParam().options.begin(), GetParam().options.end());
  // Uninterrupted runs: what a finished file is, and how long one takes (the quicker of two, once GDAL's
  // files are in the page cache, so that the moments below fall inside a run).
  auto duration = Clock::duration::max();
  for (int run = 0; run < 2; ++run) {
    const auto start = Clock::now();
    ASSERT_EQ(waitFor(startStrata(arguments)), 0);
    duration = std::min(duration, Clock::now() - start);
    if (run == 0) fs::remove(output);
  }
  const std::string finished = fingerprint(output);
  ASSERT_NE(finished, "unreadable");
  int interrupted = 0;
  for (double fraction : {0.05, 0.3, 0.55, 0.8, 0.95}) {
    fs::remove(output);
    const pid_t child = startStrata(arguments);
    ASSERT_GT(child, 0);
    std::this_thread::sleep_for(std::chrono::duration_cast<Clock::duration>(duration * fraction));
    kill(child, SIGINT);
    const int status = waitFor(child);
    const bool whole = fs::exists(output);
    SCOPED_TRACE("SIGINT at " + std::to_string(fraction) + " of a run");
    EXPECT_TRUE((WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) || (WIFEXITED(status) && WEXITSTATUS(status) == 0))
        << "status " << status;
    const std::vector<std::string> left =
        whole ? std::vector<std::string>{"in.tif", "out.tif"} : std::vector<std::string>{"in.tif"};
    EXPECT_EQ(namesIn(file("work")), left) << "no temporary file";
    if (whole) {
      EXPECT_EQ(fingerprint(output), finished) << "a file under the final name is the finished one";
    } else {
      ++interrupted;
    }
  }
  EXPECT_GE(interrupted, 2) << "the signals at 5 and 30 % of a run land while the pyramid is being written";
}

// A copy into a COG with overviews (GDAL's *.ovr.tmp), a reprojection (*.warped.tif.tmp), a HEALPix
// pyramid (the strip of faces).
INSTANTIATE_TEST_SUITE_P(EachWayOfWriting, InterruptedTile,
                         ::testing::Values(WayOfWriting{"Copy", {}, 0.05},
                                           WayOfWriting{"Reprojection", {"--to", "polar-north"}, 0.2},
                                           WayOfWriting{"Healpix", {"--to", "healpix", "--nside", "512"}, 0.2}),
                         [](const ::testing::TestParamInfo<WayOfWriting>& way) { return std::string(way.param.name); });

}  // namespace
}  // namespace strata::test
