// geometry.bdam drawn for real from patches built here (EGM96's geoid, proj-data, exaggerated on the Earth's radius,
// leaves of level 8): every pixel of the planet covered and no other, from 100,000 km to 2 m, looking down, tilted to
// the horizon, over the pole, at a cube's corner and across the antimeridian, so that no crack opens between patches of
// one level, of neighbouring levels or across the cube's edges; and the same planet as geometry.icosahedral draws over
// the same heights (source.gdal of the geoid, scale 2000).
//
// The reference spheres are the data's own lowest and highest (the face files' headers): a pixel whose ray meets the
// lower shows terrain, one whose ray misses the upper shows the sky; pixels whose neighbours one pixel away
// (diagonally) disagree are left out, as in coverage_test.cpp. The eye must stay above the upper sphere for that, so
// the geoid is exaggerated less the lower the view: x2000 (+-200 km) from 1,000 km and above, x20 (+-2 km) from 100
// and 10 km, x0.01 (+-1 m) from 2 m.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include <strata/log.hpp>

#include "bdam_data.hpp"
#include "bintree_builder.hpp"
#include "cube_bintree.hpp"
#include "face_file.hpp"
#include "image_agreement.hpp"
#include "raster_heights.hpp"
#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr double kEarth = 6371000.0;  // m
constexpr int kWidth = 320, kHeight = 240;
const char* const kGeoid = "/usr/share/proj/egm96_15.gtx";

// The face files of the geoid times `scale`, built once for the test program.
const std::filesystem::path& builtGeoid(double scale) {
  static std::map<double, TemporaryDirectory> folders;
  if (const auto built = folders.find(scale); built != folders.end()) return built->second.path();
  const std::filesystem::path& folder = folders[scale].path();
  const bdam::RasterHeights geoid(kGeoid);
  const bdam::BuiltBintrees bintrees = bdam::buildBintrees(
      [&geoid, scale]() -> bdam::HeightAt {
        return [sample = geoid.sampler(), scale](const glm::dvec3& d) { return scale * sample(d); };
      },
      {kEarth, 8, 16, 0, folder}, [](const bdam::LevelReport&) {});
  for (int face = 0; face < bdam::kCubeFaces; ++face)
    bdam::writeFaceFile(folder / ("face-" + std::to_string(face) + ".bdam"), face, bintrees);
  return folder;
}

std::string pipelineWith(const std::string& terrain, const std::string& shading) {
  return "strata: 1\nbody: {name: Earth, radius: " + std::to_string(kEarth) +
         "}\nnodes:\n"
         "  imagery: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, kind: color}\n"
         "  relief: {type: source.gdal, path: " +
         std::string(kGeoid) +
         ", kind: height, scale: 2000}\n"
         "  terrain: " +
         terrain +
         "\n"
         "  frame: {type: output.image, geometry: terrain, surface: [imagery], shading: " +
         shading + ", antialiasing: none}\n";
}

std::string bdamTerrain(double scale) { return "{type: geometry.bdam, path: " + builtGeoid(scale).string() + "}"; }

int raysMeeting(const View& view, double radius, int x, int y) {
  int meeting = 0;
  for (const int dx : {-1, 1})
    for (const int dy : {-1, 1}) meeting += raycastSphere(view, radius, x + dx, y + dy).has_value();
  return meeting;
}

struct Scene {
  const char* name;
  double lon, lat, altitude;
  double scale;  // of the geoid
  std::vector<double> tilts;
};

class BdamCoverage : public ::testing::TestWithParam<Scene> {};

TEST_P(BdamCoverage, EveryPixelOfThePlanetIsDrawnAndNoOther) {
  const Scene& scene = GetParam();
  const HeightRange heights = bdam::BdamData(builtGeoid(scene.scale)).heights();
  TemporaryDirectory directory;
  auto engine = makeEngine();
  engine->load(directory.write("bdam.yaml", pipelineWith(bdamTerrain(scene.scale), "none")));
  for (const double tilt : scene.tilts) {
    const Camera camera{
        .lon = scene.lon, .lat = scene.lat, .altitude = scene.altitude, .heading = 30.0, .tilt = tilt, .fov = 50.0};
    const Image image = renderFrames(*engine, camera, kWidth, kHeight, 1);
    const View view = makeView(engine->pipeline().body, camera, kWidth, kHeight);
    int holes = 0, strays = 0, judged = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        if (raysMeeting(view, kEarth + heights.lowest, x, y) == 4) {
          ++judged;
          holes += !covered(image, x, y);
        } else if (raysMeeting(view, kEarth + heights.highest, x, y) == 0) {
          ++judged;
          strays += covered(image, x, y);
        }
      }
    std::printf("%s, tilt %3.0f: %d holes, %d strays, %d pixels judged\n", scene.name, tilt, holes, strays, judged);
    EXPECT_EQ(holes, 0) << "tilt " << tilt;
    EXPECT_EQ(strays, 0) << "tilt " << tilt;
    EXPECT_GT(judged, kWidth * kHeight / 2);
  }
}

INSTANTIATE_TEST_SUITE_P(Views, BdamCoverage,
                         ::testing::Values(Scene{"FromFarAway", 10.0, 20.0, 1.0e8, 2000.0, {0.0, 25.0}},
                                           Scene{"FromOrbit", 10.0, 20.0, 2.0e7, 2000.0, {0.0, 12.0, 30.0}},
                                           Scene{
                                               "AcrossTheAntimeridian", 180.0, -30.0, 1.0e6, 2000.0, {0.0, 60.0, 85.0}},
                                           Scene{"OverThePole", 45.0, 90.0, 1.0e5, 20.0, {0.0, 60.0, 88.0}},
                                           Scene{"AtACubeCorner", 45.0, 35.26, 1.0e4, 20.0, {0.0, 80.0, 88.0}},
                                           Scene{"FromTwoMetres", 137.4, -4.6, 2.0, 0.01, {0.0, 88.0, 180.0}}),
                         [](const ::testing::TestParamInfo<Scene>& scene) { return std::string(scene.param.name); });

TEST(BdamAgreement, DrawsTheSamePlanetAsTheIcosahedralGenerator) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  for (const Camera& camera : {Camera{.lon = 10, .lat = 20, .altitude = 2.0e7, .tilt = 0, .fov = 45},
                               Camera{.lon = 30, .lat = 25, .altitude = 2.0e6, .heading = 40, .tilt = 40, .fov = 45}}) {
    engine->load(directory.write("bdam.yaml", pipelineWith(bdamTerrain(2000.0), "none")));
    const Image bdam = renderFrames(*engine, camera, kWidth, kHeight, 1);
    engine->load(
        directory.write("icosahedral.yaml", pipelineWith("{type: geometry.icosahedral, height: relief}", "none")));
    const Image icosahedral = renderFrames(*engine, camera, kWidth, kHeight, 3);
    const ImageAgreement agreement = agreementAwayFromSilhouettes(bdam, icosahedral);
    std::printf(
        "%8.0f m up, tilt %2.0f: %d pixels compared, mean difference %.2f levels, %.2f%% differ by more than %d\n",
        camera.altitude, camera.tilt, agreement.compared, agreement.meanDifference, 100.0 * agreement.largeShare,
        kLargeDifference);
    EXPECT_GT(agreement.compared, kWidth * kHeight / 10);
    EXPECT_LT(agreement.meanDifference, 4.0);
    EXPECT_LT(agreement.largeShare, 0.04);
  }
}

// A patch damaged on disk under the view: reported once, naming the file and the node, and the coarser patch above it
// drawn in its place, with no hole (docs/bdam.md, "The generator").
TEST(BdamDamage, ADamagedPatchIsReportedAndTheCoarserOneDrawnInItsPlace) {
  const TemporaryDirectory folder;
  for (const auto& file : std::filesystem::directory_iterator(builtGeoid(2000.0)))
    std::filesystem::copy_file(file.path(), folder.path() / file.path().filename());
  const Camera camera{.lon = 30.0, .lat = 25.0, .altitude = 2.0e5, .tilt = 0.0, .fov = 50.0};
  const glm::dvec2 place = glm::radians(glm::dvec2(camera.lon, camera.lat));
  const bdam::BintreeNode leaf = bdam::nodeContaining(unitNormal(place.x, place.y), 8);
  const std::filesystem::path face = folder.path() / ("face-" + std::to_string(leaf.root / 2) + ".bdam");
  {  // the record's patch offset (face_file.hpp's layout), and a byte in the middle of its patch changed
    std::fstream bytes(face, std::ios::in | std::ios::out | std::ios::binary);
    const std::uint64_t slot = std::uint64_t(leaf.root % 2) * ((std::uint64_t(2) << 8) - 1) + (1u << 8) - 1 + leaf.path;
    std::uint64_t offset = 0;
    bytes.seekg(std::streamoff(88 + 56 * slot));
    bytes.read(reinterpret_cast<char*>(&offset), sizeof offset);
    bytes.seekp(std::streamoff(offset + 40));
    bytes.put('\x5a');
  }
  std::vector<LogMessage> warnings;
  const LogSink previous = setLogSink([&warnings](const LogMessage& message) { warnings.push_back(message); });
  TemporaryDirectory directory;
  auto engine = makeEngine();
  engine->load(directory.write(  // half a pixel: the leaves under the eye are wanted
      "bdam.yaml",
      pipelineWith("{type: geometry.bdam, pixel_error: 0.5, path: " + folder.path().string() + "}", "none")));
  const Image image = renderFrames(*engine, camera, kWidth, kHeight, 2);
  setLogSink(previous);
  const std::string node = "bintree " + std::to_string(leaf.root) + ", level 8, node " + std::to_string(leaf.path);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].text.find(face.string() + ": " + node + ": its patch is damaged"), std::string::npos)
      << warnings[0].text;
  EXPECT_NE(warnings[0].text.find("the coarser patch above it is drawn instead"), std::string::npos);
  int holes = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) holes += !covered(image, x, y);
  EXPECT_EQ(holes, 0) << "the view from 200 km looks at the ground alone";
}

// geometry.bdam's patch slots take their graphics memory out of the pipeline's page cache budget: the cache keeps
// them aside and its atlases share the rest; a cache_mb the budget cannot hold is an error at cache_mb's line.
TEST(BdamMemory, ThePatchSlotsComeOutOfThePageCacheBudget) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const Camera camera{.lon = 10, .lat = 20, .altitude = 2.0e7};
  engine->load(
      directory.write("icosahedral.yaml", pipelineWith("{type: geometry.icosahedral, height: relief}", "none")));
  renderFrames(*engine, camera, kWidth, kHeight, 1);
  const PageCacheStatistics alone = engine->pageCacheStatistics();
  engine->load(directory.write("bdam.yaml", pipelineWith(bdamTerrain(2000.0), "none")));
  renderFrames(*engine, camera, kWidth, kHeight, 1);
  const PageCacheStatistics& shared = engine->pageCacheStatistics();
  EXPECT_EQ(alone.reservedBytes, 0u);
  EXPECT_LE(shared.reservedBytes, 64'000'000u);  // cache_mb's default, in slots of the largest patch (a few KB)
  EXPECT_GT(shared.reservedBytes, 63'900'000u);
  EXPECT_LT(shared.capacity, alone.capacity);
  EXPECT_LE(shared.gpuBytes + shared.stagingBytes + shared.reservedBytes, std::uint64_t(256) << 20);

  const std::string crowded =
      "strata: 1\ncache: {budget: 64}\n" +
      pipelineWith("{type: geometry.bdam, cache_mb: 100, path: " + builtGeoid(2000.0).string() + "}", "none")
          .substr(10);
  try {
    engine->load(directory.write("crowded.yaml", crowded));
    FAIL() << "a cache_mb beyond the budget loaded";
  } catch (const Error& error) {
    EXPECT_EQ(error.where().line, 7) << error.what();  // the terrain node's, where cache_mb is
    EXPECT_NE(error.problem().find("more than the 64 MiB the pipeline's page cache budget has left"), std::string::npos)
        << error.problem();
    EXPECT_NE(error.fix().find("raise `cache: {budget: MiB}`"), std::string::npos) << error.fix();
  }
}

}  // namespace
}  // namespace strata::test
