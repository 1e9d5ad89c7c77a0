// geometry.clipmap's height clipmaps keep what a fresh view would sample: moved frame by frame (each window
// sampling only the texels it moves in, toroidally), across the antimeridian, up to the north pole and at Gale
// crater's place; with pages arriving after a frame drew their coarser stand-ins; and with a time series of heights
// moving on. The terrain is real: EGM96's geoid (proj-data) exaggerated 1000 times (+-100 km; 10 times where the view
// comes down to 2 km), one grey lit by the geometry's normals, so that a height or a slope kept stale shows.
// Tolerance, 0.1 level on average and no pixel by more than 16: texels sampled from another frame's reference
// differ from a fresh frame's by float rounding (a height of 100 km by millimetres), a level at most where it shows.
// Measured on llvmpipe: 0.000 levels in every case. Made to fail on purpose, they showed: windows moved east without
// sampling the columns they moved in, 1.2 levels across the antimeridian; the pages' arrival ignored, 1.0; the
// date's, 0.46.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>

#include <strata/date.hpp>

#include "image_agreement.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 320, kHeight = 200;
constexpr double kMeanTolerance = 0.1;  // levels

void expectAlike(const Image& kept, const Image& fresh, const std::string& what) {
  const ImageAgreement agreement = agreementAwayFromSilhouettes(kept, fresh);
  std::printf("%s: %d pixels compared, mean difference %.3f levels, %.3f%% differ by more than %d\n", what.c_str(),
              agreement.compared, agreement.meanDifference, 100.0 * agreement.largeShare, kLargeDifference);
  EXPECT_GT(agreement.compared, kWidth * kHeight / 4) << what;
  EXPECT_LT(agreement.meanDifference, kMeanTolerance) << what;
  EXPECT_EQ(agreement.largeShare, 0.0) << what;
}

struct Move {
  const char* name;
  Camera from, to;
  int scale = 1000;  // the geoid's exaggeration: low enough that the ground stays below the camera
};
void PrintTo(const Move& move, std::ostream* out) { *out << move.name; }

// A surface of one grey, so that the shading is all the frame shows.
std::filesystem::path greySurface(const TemporaryDirectory& directory) {
  const std::filesystem::path grey = directory.path() / "grey.tif";
  writeColourRaster(grey, 8, 8, {-180, -90, 180, 90}, [](int, int) { return Rgb8{180, 180, 180}; });
  return grey;
}

// The pipeline file of one grey on geometry.clipmap over the height node `heights`, which `nodes` declares; `header`:
// lines before the nodes.
std::filesystem::path clipmapPipeline(const TemporaryDirectory& directory, const std::string& nodes,
                                      const std::string& heights, const std::string& header = "") {
  return directory.write("clipmap.yaml", "strata: 1\n" + header + "nodes:\n  grey: {type: source.gdal, path: " +
                                             greySurface(directory).string() + "}\n" + nodes +
                                             "  globe: {type: geometry.clipmap, height: " + heights +
                                             "}\n  frame: {type: output.image, geometry: globe, surface: [grey]}\n");
}

// EGM96's geoid exaggerated `scale` times.
std::string geoidNode(const std::string& name, int scale) {
  return "  " + name +
         ": {type: source.gdal, path: /usr/share/proj/egm96_15.gtx, kind: height, scale: " + std::to_string(scale) +
         "}\n";
}

class ClipmapHeights : public ::testing::TestWithParam<Move> {};

// 24 frames from one camera to the other, then the last view drawn by a fresh engine.
TEST_P(ClipmapHeights, AViewMovedFrameByFrameDrawsWhatAFreshViewDraws) {
  const Move& move = GetParam();
  TemporaryDirectory directory;
  const auto pipeline = clipmapPipeline(directory, geoidNode("geoid", move.scale), "geoid");
  auto moving = makeEngine();
  moving->load(pipeline);
  renderFrames(*moving, move.from, kWidth, kHeight, 1);
  constexpr int kSteps = 24;
  for (int step = 1; step <= kSteps; ++step) {
    const double t = double(step) / kSteps;
    Camera& camera = moving->camera();
    camera.lon = move.from.lon + t * (move.to.lon - move.from.lon);
    camera.lat = move.from.lat + t * (move.to.lat - move.from.lat);
    camera.altitude = move.from.altitude + t * (move.to.altitude - move.from.altitude);
    moving->render(kWidth, kHeight);
  }
  const Image kept = renderFrames(*moving, move.to, kWidth, kHeight, 1);
  auto fresh = makeEngine();
  fresh->load(pipeline);
  expectAlike(kept, renderFrames(*fresh, move.to, kWidth, kHeight, 1), move.name);
}

INSTANTIATE_TEST_SUITE_P(Moves, ClipmapHeights,
                         ::testing::Values(Move{"across the antimeridian",
                                                {.lon = 179.0, .lat = -30, .altitude = 3e5, .heading = 90, .tilt = 40},
                                                {.lon = 181.0, .lat = -30, .altitude = 3e5, .heading = 90, .tilt = 40}},
                                           Move{"up to the north pole",
                                                {.lon = 30, .lat = 87.0, .altitude = 2e5, .tilt = 30},
                                                {.lon = 30, .lat = 89.99, .altitude = 2e5, .tilt = 30}},
                                           Move{"down to Gale crater",
                                                {.lon = 137.0, .lat = -4.0, .altitude = 2e5, .tilt = 50},
                                                {.lon = 137.4, .lat = -4.6, .altitude = 2e3, .tilt = 50},
                                                10}),
                         [](const ::testing::TestParamInfo<Move>& move) { return std::to_string(move.index); });

// A first frame drawn while the finer pages of a height layer were still loading samples their coarser stand-ins;
// the pages' arrival (Layer::revision) samples every texel again. The heights: the Blue Marble's first band
// (2048 x 1024, four pages and their pinned overview) as metres times 400, rough where the geoid is smooth.
TEST(ClipmapHeightsAsPagesArrive, TheyReplaceTheHeightsOfTheirStandIns) {
  TemporaryDirectory directory;
  const auto pipeline = clipmapPipeline(
      directory,
      "  bands: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, kind: height, band: 1, scale: 400}\n",
      "bands");
  const Camera camera{.lon = -70, .lat = -15, .altitude = 5e5, .tilt = 45};
  auto loading = makeEngine();
  loading->load(pipeline);
  loading->camera() = camera;
  loading->render(kWidth, kHeight);
  ASSERT_GT(loading->pageCacheStatistics().loading, 0) << "the first frame drew stand-ins";
  const Image loaded = renderFrames(*loading, camera, kWidth, kHeight, 1);
  auto fresh = makeEngine();
  fresh->load(pipeline);
  expectAlike(loaded, renderFrames(*fresh, camera, kWidth, kHeight, 1), "pages arrived");
}

// A time series of heights (the geoid at two exaggerations a month apart) moved to another date: every texel
// is sampled again.
TEST(ClipmapHeightsInTime, ADateMovedOnSamplesTheSeriesAgain) {
  TemporaryDirectory directory;
  const auto pipeline = clipmapPipeline(
      directory,
      geoidNode("low", 200) + geoidNode("high", 1000) +
          "  geoid: {type: composite.temporal_blend, steps: [low, high], dates: [2004-01-15, 2004-02-15]}\n",
      "geoid", "date: 2004-01-15\n");
  const Camera camera{.lon = 100, .lat = 10, .altitude = 1e6, .tilt = 45};
  auto stepping = makeEngine();
  stepping->load(pipeline);
  const Image january = renderFrames(*stepping, camera, kWidth, kHeight, 1);
  stepping->date() = parseIsoDate("2004-02-10");
  const Image february = renderFrames(*stepping, camera, kWidth, kHeight, 1);
  auto fresh = makeEngine();
  fresh->load(pipeline);
  fresh->date() = parseIsoDate("2004-02-10");
  expectAlike(february, renderFrames(*fresh, camera, kWidth, kHeight, 1), "the date moved on");
  EXPECT_GT(agreementAwayFromSilhouettes(january, february).meanDifference, 4.0 * kMeanTolerance)
      << "the heights changed enough for stale ones to show";
}

}  // namespace
}  // namespace strata::test
