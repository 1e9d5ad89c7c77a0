// Every recipe in pipelines/ is documentation and a smoke test at once: each must render with the built
// command, from the source tree, to a frame that shows a body against space.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

std::vector<std::string> samplePipelines() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(STRATA_SOURCE_DIR) / "pipelines"))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  return names;
}

class SamplePipeline : public StrataCommandTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SamplePipeline, RendersABodyAgainstSpace) {
  const std::filesystem::path png = file("frame.png");
  const CommandResult result =
      run({"render", "pipelines/" + GetParam() + ".yaml", "--size", "160x90", "-o", png.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const Image image = readImage(png);
  const auto corner = image.at(0, 0), centre = image.at(80, 45);
  EXPECT_EQ(corner[0] + corner[1] + corner[2], 0) << "space in the corner";
  EXPECT_GT(centre[0] + centre[1] + centre[2], 60) << "a lit body in the centre";
}

INSTANTIATE_TEST_SUITE_P(Recipes, SamplePipeline, ::testing::ValuesIn(samplePipelines()), [](const auto& test) {
  // A test's name takes letters, digits and underscores: bench-flyin is bench_flyin.
  std::string name = test.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

}  // namespace
}  // namespace strata::test
