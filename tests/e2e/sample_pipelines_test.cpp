// Every recipe in pipelines/ is documentation and a smoke test at once: each must render with the built
// command, from the source tree, to a frame that shows a body against space; and each that names a geometry
// generator renders as well with geometry.clipmap in its place (issue 30), its heights and their bounds kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

std::filesystem::path samplePath(const std::string& name) {
  return std::filesystem::path(STRATA_SOURCE_DIR) / "pipelines" / (name + ".yaml");
}

// The recipes' names; with `scenes` false, without the scenes of several bodies (`bodies:`), whose bodies are
// drawn by recipes of their own (earth_moon.yaml by day_night.yaml and moon.yaml).
std::vector<std::string> samplePipelines(bool scenes = true) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(STRATA_SOURCE_DIR) / "pipelines"))
    if (entry.path().extension() == ".yaml" && (scenes || !YAML::LoadFile(entry.path().string())["bodies"]))
      names.push_back(entry.path().stem().string());
  return names;
}

// `--set` overrides that put geometry.clipmap in place of every geometry generator of pipeline `name`, with the
// generator's height input and bounds and none of its own parameters.
std::vector<std::string> withClipmaps(const std::string& name) {
  const YAML::Node pipeline = YAML::LoadFile(samplePath(name).string());
  std::vector<std::string> overrides;
  for (const auto& node : pipeline["nodes"]) {
    if (node.second["type"].as<std::string>().rfind("geometry.", 0) != 0) continue;
    YAML::Node clipmap;
    clipmap["type"] = "geometry.clipmap";
    for (const char* kept : {"height", "lowest", "highest"})
      if (node.second[kept]) clipmap[kept] = node.second[kept];
    YAML::Emitter flow;
    flow << YAML::Flow << clipmap;
    overrides.insert(overrides.end(), {"--set", "nodes." + node.first.as<std::string>() + "=" + flow.c_str()});
  }
  return overrides;
}

class SamplePipeline : public StrataCommandTest, public ::testing::WithParamInterface<std::string> {
 protected:
  // Renders the pipeline with `overrides` and judges the frame.
  void rendersABodyAgainstSpace(const std::vector<std::string>& overrides) {
    const std::filesystem::path png = file("frame.png");
    std::vector<std::string> arguments = {
        "render", "pipelines/" + GetParam() + ".yaml", "--size", "160x90", "-o", png.string(), "--overwrite"};
    arguments.insert(arguments.end(), overrides.begin(), overrides.end());
    const CommandResult result = run(arguments);
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const Image image = readImage(png);
    const auto corner = image.at(0, 0), centre = image.at(80, 45);
    EXPECT_EQ(corner[0] + corner[1] + corner[2], 0) << "space in the corner";
    EXPECT_GT(centre[0] + centre[1] + centre[2], 60) << "a lit body in the centre";
  }
};

TEST_P(SamplePipeline, RendersABodyAgainstSpace) { rendersABodyAgainstSpace({}); }

// The recipes of one body, whose generators --set reaches.
using OneBodySamplePipeline = SamplePipeline;

TEST_P(OneBodySamplePipeline, RendersWithSphericalClipmapsInPlaceOfItsGenerators) {
  const std::vector<std::string> overrides = withClipmaps(GetParam());
  ASSERT_FALSE(overrides.empty()) << "output.image draws a geometry: every recipe names a generator";
  rendersABodyAgainstSpace(overrides);
}

// A test's name takes letters, digits and underscores: bench-flyin is bench_flyin.
std::string testName(const ::testing::TestParamInfo<std::string>& test) {
  std::string name = test.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Recipes, SamplePipeline, ::testing::ValuesIn(samplePipelines()), testName);
INSTANTIATE_TEST_SUITE_P(Recipes, OneBodySamplePipeline, ::testing::ValuesIn(samplePipelines(false)), testName);

}  // namespace
}  // namespace strata::test
