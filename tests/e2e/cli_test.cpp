// End-to-end tests of the strata command. Each runs the built binary as a user would, from the source tree
// (where pipelines/ is), and checks its exit code, what it prints and the images it writes. Frames are
// small so that the suite stays quick on llvmpipe.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "strata_command.hpp"
#include "test_rasters.hpp"

namespace {

namespace fs = std::filesystem;

using strata::test::CommandResult;
using strata::test::contains;
using strata::test::Image;
using strata::test::readImage;
using strata::test::readText;
using strata::test::StrataCommandTest;

// A pixel without its alpha, which is always opaque in a rendered frame.
std::array<int, 3> rgb(const Image& image, int x, int y) {
  const std::array<int, 4> rgba = image.at(x, y);
  return {rgba[0], rgba[1], rgba[2]};
}

// The first line of `text` that starts with `prefix`, or "" when none does: listings print one item a line.
std::string lineStartingWith(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with(prefix)) return line;
  return {};
}

bool hasLineStartingWith(const std::string& text, const std::string& prefix) {
  return !lineStartingWith(text, prefix).empty();
}

// Each of `prefixes` begins some line of `text` (listings of types, parameters and libraries).
void expectLinesStartingWith(const std::string& text, std::initializer_list<const char*> prefixes) {
  for (const char* prefix : prefixes)
    EXPECT_TRUE(hasLineStartingWith(text, prefix)) << "no line starting '" << prefix << "' in:\n" << text;
}

// The number of bands GDAL finds in `file` (0 when it cannot open it): a PNG frame is RGB or RGBA.
int bandCount(const fs::path& file) {
  GDALAllRegister();
  GDALDatasetH dataset = GDALOpen(file.c_str(), GA_ReadOnly);
  if (!dataset) return 0;
  const int bands = GDALGetRasterCount(dataset);
  GDALClose(dataset);
  return bands;
}

// --- render: the demo pipeline ------------------------------------------------------------------------

// Channel differences larger than rounding: lighting scales r, g and b alike, so a grey surface stays
// within a level or two of grey, and 24 levels of 255 can only come from the imagery's colours.
constexpr int kHueMargin = 24;

TEST_F(StrataCommandTest, RenderDrawsTheDemoEarthAgainstBlackSpace) {
  const fs::path png = file("demo.png");
  const CommandResult result = run({"render", "pipelines/demo.yaml", "--size", "320x180", "-o", png.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "wrote")) << result.out;
  const int bands = bandCount(png);
  EXPECT_TRUE(bands == 3 || bands == 4) << bands << " bands";
  const Image image = readImage(png);
  ASSERT_EQ(image.width, 320);
  ASSERT_EQ(image.height, 180);
  // At 20,000 km with a 45 degree field of view the globe spans about 60% of the frame's height, so the
  // corners look past it into space, which is exactly black; the centre looks at the lit day side.
  for (auto [x, y] : {std::array{0, 0}, {319, 0}, {0, 179}, {319, 179}})
    EXPECT_EQ(rgb(image, x, y), (std::array{0, 0, 0})) << "corner " << x << "," << y;
  const std::array<int, 3> centre = rgb(image, 160, 90);
  EXPECT_GT(centre[0] + centre[1] + centre[2], 150) << "the centre of the globe is (nearly) black";
}

TEST_F(StrataCommandTest, RenderDrapesImageryWithBothOceanAndLandColours) {
  const fs::path png = file("demo.png");
  const CommandResult result = run({"render", "pipelines/demo.yaml", "--size", "320x180", "-o", png.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const Image image = readImage(png);
  // A flat surface would shade to greys; the Blue Marble seen over Africa shows blue ocean and tan land,
  // each on about 40% of the globe on llvmpipe.
  int globe = 0, bluish = 0, reddish = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto [r, g, b] = rgb(image, x, y);
      if (r + g + b == 0) continue;  // space
      ++globe;
      bluish += b > r + kHueMargin;
      reddish += r > b + kHueMargin;
    }
  ASSERT_GT(globe, 320 * 180 / 10) << "the globe covers less than a tenth of the frame";
  EXPECT_GT(bluish, globe / 5) << "under 20% of the globe is ocean-coloured";
  EXPECT_GT(reddish, globe / 5) << "under 20% of the globe is land-coloured";
}

// --dates: a frame sequence through the scene's date. pipelines/temporal_blend.yaml looks at 35 degrees north,
// where January's snow reaches 40 degrees and July's draws back to 85: January's frame is the whiter.
TEST_F(StrataCommandTest, RenderSweepsThroughTheScenesDate) {
  const std::string pattern = file("year_%02d.png").string();
  const CommandResult result = run({"render", "pipelines/temporal_blend.yaml", "--size", "96x72", "--dates",
                                    "2004-01-01/2004-07-01", "--frames", "3", "-o", pattern});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "wrote 3 frames")) << result.out;
  std::array<double, 3> brightness{};
  for (int frame = 0; frame < 3; ++frame) {
    const Image image = readImage(file("year_0" + std::to_string(frame) + ".png"));
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const auto [r, g, b] = rgb(image, x, y);
        brightness[std::size_t(frame)] += (r + g + b) / (3.0 * image.width * image.height);
      }
  }
  std::printf("mean brightness: January %.1f, April %.1f, July %.1f\n", brightness[0], brightness[1], brightness[2]);
  EXPECT_GT(brightness[0], brightness[1] + 5.0);
  EXPECT_GT(brightness[1], brightness[2]);
}

// output.image shows the frame through an OpenColorIO display and view (docs/colour.md); one the config lacks
// is named at its line with the ones there are.
TEST_F(StrataCommandTest, UnknownDisplayNamesTheDisplaysThereAre) {
  const auto pipeline = write("p.yaml",
                              "strata: 1\nnodes:\n  g: {type: geometry.icosahedral}\n"
                              "  f: {type: output.image, geometry: g, display: P3}\n");
  const CommandResult result = renderTiny(pipeline);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "p.yaml:4:")) << result.err;
  EXPECT_TRUE(contains(result.err, "the display 'P3' is not in Strata's built-in config")) << result.err;
  EXPECT_TRUE(contains(result.err, "choose one of 'sRGB'")) << result.err;
}

// A config given in the pipeline is the one used: a copy of Strata's whose display is called "Wall".
TEST_F(StrataCommandTest, PipelineChoosesItsColourConfig) {
  std::string config = readText(fs::path(STRATA_SOURCE_DIR) / "ocio" / "strata.ocio");
  for (std::size_t at; (at = config.find("sRGB:")) != std::string::npos;) config.replace(at, 5, "Wall:");
  for (std::size_t at; (at = config.find("[sRGB]")) != std::string::npos;) config.replace(at, 6, "[Wall]");
  write("wall.ocio", config);
  const std::string scene = "strata: 1\ncolour: {config: wall.ocio}\nnodes:\n  g: {type: geometry.icosahedral}\n";
  const CommandResult wall = renderTiny(write("wall.yaml", scene + "  f: {type: output.image, geometry: g}\n"));
  EXPECT_EQ(wall.exitCode, 0) << wall.err;
  const CommandResult srgb =
      renderTiny(write("srgb.yaml", scene + "  f: {type: output.image, geometry: g, display: sRGB}\n"));
  EXPECT_EQ(srgb.exitCode, 1);
  EXPECT_TRUE(contains(srgb.err, "wall.ocio")) << srgb.err;
  EXPECT_TRUE(contains(srgb.err, "choose one of 'Wall'")) << srgb.err;
}

TEST_F(StrataCommandTest, RenderSweepNeedsAFileNameField) {
  const CommandResult result = run({"render", "pipelines/temporal_blend.yaml", "--dates", "2004-01-01/2004-07-01",
                                    "--frames", "3", "-o", file("year.png").string()});
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(contains(result.err, "-o: error:")) << result.err;
  EXPECT_TRUE(contains(result.err, "%04d")) << result.err;
}

// --stats: with geometry.icosahedral's defaults (300 patches of depth 5: 561 vertices and 1024 triangles
// each, fewer triangles along edges that meet coarser neighbours) the numbers follow from the patches.
TEST_F(StrataCommandTest, RenderStatsCountPatchesVerticesAndTriangles) {
  const CommandResult result =
      run({"render", "pipelines/demo.yaml", "--size", "320x180", "-o", file("demo.png").string(), "--stats"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  unsigned long long frames = 0, vertices = 0, triangles = 0;
  int patches = 0;
  const std::size_t at = result.out.find("strata: last of");
  ASSERT_NE(at, std::string::npos) << result.out;
  ASSERT_EQ(
      std::sscanf(result.out.c_str() + at, "strata: last of %llu frames: %d patches, %llu vertices, %llu triangles",
                  &frames, &patches, &vertices, &triangles),
      4)
      << result.out;
  EXPECT_GE(frames, 1u);
  EXPECT_GT(patches, 0);
  EXPECT_LE(patches, 300) << "the default cap";  // at 320x180 the pixel error asks for 15 of them
  EXPECT_EQ(vertices, 561ull * unsigned(patches));
  EXPECT_LE(triangles, 1024ull * unsigned(patches));
  EXPECT_GT(triangles, 900ull * unsigned(patches));
  for (const char* phase : {"visibility", "subdivision", "rasterisation", "page cache"})
    EXPECT_TRUE(contains(result.out, phase)) << result.out;
}

TEST_F(StrataCommandTest, RenderToAnUnwritablePathFailsWithAMessage) {
  const CommandResult result = run({"render", "pipelines/demo.yaml", "--size", "32x18", "-o", "/proc/strata-test.png"});
  EXPECT_EQ(result.exitCode, 1) << result.err;  // 1, not a signal or an abort
  EXPECT_TRUE(contains(result.err, "/proc/strata-test.png: error: cannot write")) << result.err;
  EXPECT_TRUE(contains(result.err, "\n  fix: ")) << result.err;
}

// --- render: pipelines with mistakes ------------------------------------------------------------------

// What every rejected pipeline must show: exit code 1 and, on stderr, the file with the line and column of
// the mistake, "error:", the words that say what is wrong, and a line that says how to fix it.
void expectRejected(const CommandResult& result, const fs::path& pipeline, int line, int column,
                    const std::vector<std::string>& words) {
  EXPECT_EQ(result.exitCode, 1) << result.err;
  const std::string location = pipeline.string() + ":" + std::to_string(line) + ":" + std::to_string(column);
  EXPECT_TRUE(contains(result.err, location)) << "expected " << location << " in:\n" << result.err;
  EXPECT_TRUE(contains(result.err, "error:")) << result.err;
  EXPECT_TRUE(contains(result.err, "\n  fix: ")) << result.err;
  for (const std::string& word : words)
    EXPECT_TRUE(contains(result.err, word)) << "no '" << word << "' in:\n" << result.err;
}

// A pipeline whose first node is `first`; the rest is a plain globe with one imagery layer. Line 4 is the
// first line of `first`.
std::string pipelineWith(const std::string& first) {
  return "strata: 1\n"
         "camera: {lon: 10, lat: 20, altitude: 2.0e7}\n"
         "nodes:\n" +
         first +
         "  globe:\n"
         "    type: geometry.icosahedral\n"
         "  frame:\n"
         "    type: output.image\n"
         "    geometry: globe\n"
         "    surface: [imagery]\n";
}

TEST_F(StrataCommandTest, UnknownNodeTypeSuggestsTheNearestType) {
  const fs::path pipeline = write("typo.yaml", pipelineWith("  imagery:\n"
                                                            "    type: source.gdl\n"  // line 5, value at column 11
                                                            "    path: /usr/share/xplanet/images/earth.jpg\n"));
  const CommandResult result = renderTiny(pipeline);
  expectRejected(result, pipeline, 5, 11, {"source.gdl", "source.gdal"});
}

TEST_F(StrataCommandTest, MissingDataFileIsNamedAtItsPath) {
  const fs::path pipeline = write("missing.yaml", pipelineWith("  imagery:\n"
                                                               "    type: source.gdal\n"
                                                               "    path: does-not-exist.tif\n"));  // line 6
  const CommandResult result = renderTiny(pipeline);
  expectRejected(result, pipeline, 6, 11, {"does-not-exist.tif", "not found"});
}

TEST_F(StrataCommandTest, WrongParameterTypeIsNamedAtItsValue) {
  const fs::path pipeline = write("scale.yaml", pipelineWith("  imagery:\n"
                                                             "    type: source.gdal\n"
                                                             "    path: /usr/share/xplanet/images/earth.jpg\n"
                                                             "    scale: lots\n"));  // line 7
  const CommandResult result = renderTiny(pipeline);
  expectRejected(result, pipeline, 7, 12, {"scale", "lots"});
}

TEST_F(StrataCommandTest, ColourLayerAsHeightNamesBothKinds) {
  const fs::path pipeline = write("kinds.yaml",
                                  "strata: 1\n"
                                  "nodes:\n"
                                  "  imagery:\n"
                                  "    type: source.gdal\n"
                                  "    path: /usr/share/xplanet/images/earth.jpg\n"
                                  "    kind: color\n"
                                  "  globe:\n"
                                  "    type: geometry.icosahedral\n"
                                  "    height: imagery\n"  // line 9
                                  "  frame:\n"
                                  "    type: output.image\n"
                                  "    geometry: globe\n");
  // Layer kinds are known only once the nodes are made; the message points at the input that names it.
  const CommandResult result = renderTiny(pipeline);
  expectRejected(result, pipeline, 9, 13, {"height", "color", "imagery"});
}

TEST_F(StrataCommandTest, CycleOfInputsIsShownAsAPath) {
  const fs::path pipeline = write("cycle.yaml",
                                  "strata: 1\n"
                                  "nodes:\n"
                                  "  first:\n"
                                  "    type: composite.passthrough\n"
                                  "    layer: second\n"  // line 5
                                  "  second:\n"
                                  "    type: composite.passthrough\n"
                                  "    layer: first\n"  // line 8
                                  "  globe:\n"
                                  "    type: geometry.icosahedral\n"
                                  "  frame:\n"
                                  "    type: output.image\n"
                                  "    geometry: globe\n"
                                  "    surface: [first]\n");
  const CommandResult result = renderTiny(pipeline, STRATA_E2E_PLUGIN_DIR);
  expectRejected(result, pipeline, 5, 12, {"cycle", "first -> second -> first"});
}

TEST_F(StrataCommandTest, OverrideOutOfRangeNamesTheSetOption) {
  const CommandResult result = run({"render", "pipelines/demo.yaml", "--set", "camera.altitude=-5", "--size", "32x18",
                                    "-o", file("x.png").string()});
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(result.err.starts_with("--set")) << result.err;
  EXPECT_TRUE(contains(result.err, "camera.altitude=-5")) << result.err;
  EXPECT_TRUE(contains(result.err, "altitude")) << result.err;
  EXPECT_TRUE(contains(result.err, "\n  fix: ")) << result.err;
  EXPECT_FALSE(fs::exists(file("x.png")));
}

TEST_F(StrataCommandTest, CommandLineMistakesExitWithOne) {
  const CommandResult missing = run({"render", "does-not-exist.yaml"});
  EXPECT_EQ(missing.exitCode, 1) << missing.err;
  EXPECT_TRUE(contains(missing.err, "does-not-exist.yaml")) << missing.err;
  const CommandResult size = run({"render", "pipelines/demo.yaml", "--size", "12"});
  EXPECT_EQ(size.exitCode, 1) << size.err;
  EXPECT_TRUE(contains(size.err, "--size")) << size.err;
}

// A size beyond an int is refused with what was given, not wrapped (4294967297 was read as 1: issue 37).
TEST_F(StrataCommandTest, ASizeBeyondTheLimitIsRefusedAsGiven) {
  for (const std::string size : {"4294967297x1", "99999999999999999999x1", "16385x16", "0x10", "-5x3"}) {
    const CommandResult result = run({"render", "pipelines/demo.yaml", "--size", size, "-o", file("x.png").string()});
    EXPECT_EQ(result.exitCode, 1) << size;
    EXPECT_TRUE(contains(result.err, "between 1x1 and 16384x16384 pixels, not " + size)) << result.err;
    EXPECT_FALSE(fs::exists(file("x.png"))) << size;
  }
  for (const std::string size : {"32", "32x", "32x18z", "x18", "32 x 18"}) {
    const CommandResult result = run({"render", "pipelines/demo.yaml", "--size", size, "-o", file("x.png").string()});
    EXPECT_EQ(result.exitCode, 1) << size;
    EXPECT_TRUE(contains(result.err, "WIDTHxHEIGHT")) << result.err;
  }
}

TEST_F(StrataCommandTest, HelpExitsWithZeroAndNamesTheCommands) {
  const CommandResult result = run({"--help"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  for (const char* command : {"render", "view", "bench", "plugins", "project", "info"})
    EXPECT_TRUE(contains(result.out, command)) << "no " << command << " in:\n" << result.out;
}

// --- plugins and info -----------------------------------------------------------------------------------

TEST_F(StrataCommandTest, PluginsListsTheBuiltInTypes) {
  const CommandResult result = run({"plugins"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  expectLinesStartingWith(
      result.out, {"source.gdal ", "geometry.healpix ", "geometry.icosahedral ", "geometry.pgm ", "output.image "});
}

TEST_F(StrataCommandTest, PluginsDescribesTheParametersOfAType) {
  const CommandResult result = run({"plugins", "--describe", "source.gdal"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(result.out.starts_with("source.gdal (source)")) << result.out;
  expectLinesStartingWith(result.out, {"  path ", "  kind ", "  scale "});
}

TEST_F(StrataCommandTest, PluginsRefusesToDescribeAnUnknownType) {
  const CommandResult result = run({"plugins", "--describe", "nosuch"});
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "'nosuch'")) << result.err;
  EXPECT_TRUE(contains(result.err, "\n  fix: ")) << result.err;
}

// --- project ----------------------------------------------------------------------------------------

// On a sphere of radius R the equirectangular map is x = R lon, y = R lat (radians): (10, 40) degrees on
// the Earth's sphere is (1111949.2664455874, 4447797.0657823496) m, printed to the last digit a double
// holds. The far side of an orthographic view is no point of its map.
TEST_F(StrataCommandTest, ProjectMapsPointsThroughAProjectionAndBack) {
  const std::string earth = " +R=6371000";
  const CommandResult forward =
      run({"project", "+proj=eqc" + earth, write("points.txt", "10 40\n\n-170 -60\n").string()});
  ASSERT_EQ(forward.exitCode, 0) << forward.err;
  EXPECT_EQ(forward.out, "1111949.2664455874 4447797.0657823496\n-18903137.529574987 -6671695.5986735234\n");
  const CommandResult inverse = run({"project", "--inverse", "+proj=eqc" + earth,
                                     write("xy.txt", "1111949.2664455874 4447797.0657823496\n").string()});
  ASSERT_EQ(inverse.exitCode, 0) << inverse.err;
  EXPECT_EQ(inverse.out, "10 40\n");
  const CommandResult farSide =
      run({"project", "+proj=ortho +lat_0=0 +lon_0=0" + earth, write("far.txt", "120 0\n").string()});
  ASSERT_EQ(farSide.exitCode, 0) << farSide.err;
  EXPECT_EQ(farSide.out, "outside\n");
}

TEST_F(StrataCommandTest, ProjectNamesTheLineItCannotRead) {
  const auto points = write("points.txt", "10 40\nten forty\n");
  const CommandResult result = run({"project", "+proj=eqc +R=6371000", points.string()});
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(contains(result.err, points.string() + ":2:1: error: not two numbers: 'ten forty'")) << result.err;
  EXPECT_TRUE(contains(result.err, "\n  fix: write LON LAT in degrees")) << result.err;
  const CommandResult unknown = run({"project", "+proj=sinu +R=6371000", points.string()});
  EXPECT_EQ(unknown.exitCode, 1) << unknown.err;
  EXPECT_TRUE(contains(unknown.err, "is not one of the projections Strata composes")) << unknown.err;
}

TEST_F(StrataCommandTest, InfoNamesTheLibrariesAndTheRenderer) {
  const CommandResult result = run({"info"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  expectLinesStartingWith(result.out, {"GDAL ", "PROJ ", "OpenColorIO ", "yaml-cpp "});
  // "renderer" and then the GL_RENDERER string, which a working context never leaves empty.
  const std::string renderer = lineStartingWith(result.out, "renderer ");
  EXPECT_NE(renderer.find_first_not_of(' ', std::string("renderer ").size()), std::string::npos) << result.out;
}

}  // namespace
