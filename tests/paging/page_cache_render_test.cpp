// Rendering through the page cache (strata/host/page_cache.hpp) on the headless context: a budget that holds
// a fraction of a raster's pages stays within itself, evicts as the view moves and still draws what a
// roomy cache draws; a page that cannot be read is stood in for by the coarser level; a moving view finds its pages
// read ahead.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>

#include <gdal_priv.h>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 4096, kHeight = 2048;  // 8 x 4 pages at full resolution, 4 levels
constexpr int kFrame = 256;

// Luminance that varies smoothly (so a level's proxy looks like it) between 0.6 and 0.9 in linear light,
// far from the 0.18 grey drawn where no layer has data.
float smoothLuminance(int column, int row) {
  const double lon = 2.0 * std::numbers::pi * (column + 0.5) / kWidth, lat = std::numbers::pi * (row + 0.5) / kHeight;
  return float(0.75 + 0.15 * std::sin(3.0 * lon) * std::sin(2.0 * lat));
}

class PageCacheRendering : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    raster_ = new TemporaryDirectory();
    writeFloatRaster(raster_->path() / "plain.tif", kWidth, kHeight, {-180.0, -90.0, 180.0, 90.0}, smoothLuminance);
  }
  static void TearDownTestSuite() { delete raster_; }

  // A pipeline drawing `file` as luminance, unshaded, with the cache settings `cache` (YAML flow map).
  std::filesystem::path pipeline(const std::filesystem::path& file, const std::string& cache, double lon, double lat,
                                 double altitude) const {
    return scratch_.write("p.yaml",
                          "strata: 1\n"
                          "camera: {lon: " +
                              std::to_string(lon) + ", lat: " + std::to_string(lat) +
                              ", altitude: " + std::to_string(altitude) +
                              "}\n"
                              "cache: " +
                              cache +
                              "\n"
                              "nodes:\n"
                              "  data: {type: source.gdal, path: " +
                              file.string() +
                              ", kind: luminance}\n"
                              "  globe: {type: geometry.icosahedral}\n"
                              "  frame: {type: output.image, geometry: globe, surface: [data], shading: none}\n");
  }

  static TemporaryDirectory* raster_;
  TemporaryDirectory scratch_;
};

TemporaryDirectory* PageCacheRendering::raster_ = nullptr;

// The largest difference of any channel of any pixel.
int largestDifference(const Image& a, const Image& b) {
  int largest = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    largest = std::max(largest, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return largest;
}

// Overwrites the start of the full-resolution tile (column, row) of a tiled GeoTIFF, where its
// compressed stream begins, so that it cannot be decoded.
void damageTile(const std::filesystem::path& file, int column, int row) {
  std::uint64_t offset = 0;
  {
    std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    ASSERT_TRUE(dataset);
    const std::string item = "BLOCK_OFFSET_" + std::to_string(column) + "_" + std::to_string(row);
    const char* value = dataset->GetRasterBand(1)->GetMetadataItem(item.c_str(), "TIFF");
    ASSERT_NE(value, nullptr);
    offset = std::stoull(value);
  }
  std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
  stream.seekp(std::streamoff(offset));
  const std::string garbage(64, '\xA5');
  stream.write(garbage.data(), std::streamsize(garbage.size()));
}

// A budget of 67 MiB with 2 uploads a frame and 1 loader holds 13 of the raster's 43 pages (value slots of 4 MiB:
// the values and their slopes) once the staging is paid for. Where the view wants no more than that, it draws
// exactly what a cache of the default budget draws, and the cache stays within its budget.
TEST_F(PageCacheRendering, ASmallBudgetStaysWithinItselfAndDrawsWhatARoomyOneDraws) {
  const std::filesystem::path file = raster_->path() / "plain.tif";
  auto engine = makeEngine();
  const Image cramped =
      renderFrame(*engine, pipeline(file, "{budget: 67, uploads_per_frame: 2, loader_threads: 1}", 10.0, -30.0, 1.5e6),
                  kFrame, kFrame);
  const PageCacheStatistics& statistics = engine->pageCacheStatistics();
  EXPECT_EQ(statistics.capacity, 13);
  EXPECT_LE(statistics.wanted, statistics.capacity) << "the view must fit the small cache for the comparison";
  EXPECT_LE(statistics.gpuBytes + statistics.stagingBytes, std::uint64_t(67) << 20);

  auto roomy = makeEngine();
  const Image reference = renderFrame(*roomy, pipeline(file, "{}", 10.0, -30.0, 1.5e6), kFrame, kFrame);
  EXPECT_EQ(largestDifference(cramped, reference), 0);
}

TEST_F(PageCacheRendering, TheLeastRecentlyUsedPagesAreEvictedAsTheViewMoves) {
  auto engine = makeEngine();
  engine->load(pipeline(raster_->path() / "plain.tif", "{budget: 40, uploads_per_frame: 2, loader_threads: 1}", -150.0,
                        20.0, 1.5e6));
  for (const double lon : {-150.0, -60.0, 30.0, 120.0}) {
    engine->camera().lon = lon;
    engine->renderComplete(kFrame, kFrame);
  }
  const PageCacheStatistics& statistics = engine->pageCacheStatistics();
  EXPECT_GT(statistics.evicted, 0u);
  EXPECT_LE(statistics.resident, statistics.capacity);
  EXPECT_EQ(statistics.pinned, 1);  // the one page of the coarsest level
}

// The view looks down on full-resolution tile (3, 1), 1500 km below: level 0 is wanted there. With that
// tile damaged, level 1 (from the COG's overview) stands in; the field is smooth, so the picture stays
// within 2 levels of the intact one, where a masked page would show the 0.18 grey, 80 levels away. Only
// that page fails: its neighbours, whose borders it would give, clamp their borders instead.
TEST_F(PageCacheRendering, AnUnreadablePageIsStoodInForByTheCoarserLevel) {
  const std::filesystem::path intact = scratch_.path() / "intact.tif", damaged = scratch_.path() / "damaged.tif";
  const PluginRegistry plugins;
  tileRaster(plugins, {raster_->path() / "plain.tif", intact, "", false, {}});
  std::filesystem::copy_file(intact, damaged);
  damageTile(damaged, 3, 1);

  auto reference = makeEngine();
  const Image expected = renderFrame(*reference, pipeline(intact, "{}", -22.5, 22.5, 1.5e6), kFrame, kFrame);
  auto engine = makeEngine();
  const Image stoodIn = renderFrame(*engine, pipeline(damaged, "{}", -22.5, 22.5, 1.5e6), kFrame, kFrame);
  EXPECT_EQ(engine->pageCacheStatistics().failed, 1u);
  EXPECT_LE(largestDifference(expected, stoodIn), 2);
}

// A view moving east 0.3 degrees a frame, looking 100 frames (30 degrees) ahead, at level-0 pages 45 degrees wide:
// once the pages of the view ahead are read, a jump to where it looked finds every page it wants in place [Cignoni et
// al. 2003, §4.4], where without prefetch coarser pages stand in for some.
TEST_F(PageCacheRendering, AMovingViewFindsItsPagesReadAhead) {
  constexpr double kFramesAhead = 100.0;
  for (const bool prefetch : {true, false}) {
    auto engine = makeEngine();
    engine->load(pipeline(raster_->path() / "plain.tif", prefetch ? "{prefetch: true}" : "{prefetch: false}", -150.0,
                          20.0, 1.5e6));
    engine->setLookAhead(kFramesAhead);
    engine->renderComplete(kFrame, kFrame);
    Camera before = engine->camera();
    for (int frame = 0; frame < 500; ++frame) {
      before = engine->camera();
      engine->camera().lon += 0.3;
      engine->render(kFrame, kFrame);
      if (engine->pageCacheStatistics().loading == 0) break;
    }
    ASSERT_EQ(engine->pageCacheStatistics().loading, 0) << "the pages of the view ahead were not read in 500 frames";
    EXPECT_EQ(engine->pageCacheStatistics().ahead > 0, prefetch);
    engine->camera() = cameraAhead(engine->pipeline().body, before, engine->camera(), kFramesAhead);
    engine->setLookAhead(0.0);  // the arrival looks no further
    engine->render(kFrame, kFrame);
    if (prefetch)
      EXPECT_EQ(engine->pageCacheStatistics().missing, 0) << "pages the arrival wanted were not read ahead";
    else
      EXPECT_GT(engine->pageCacheStatistics().missing, 0) << "the arrival found its pages without prefetch";
  }
}

}  // namespace
}  // namespace strata::test
