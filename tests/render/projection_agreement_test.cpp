// The same planet seen through different projections gives the same picture where each projection
// samples it well ([Kooima 2008, ch. 4]: the procedural planet "observed" as global, polar, HEALPix and
// strip data). The observations are written by strata-make-test-data through PROJ, independently of
// Strata's own projection code, and rendered one at a time here; pairs of renderings are compared pixel by
// pixel over the latitudes both sample well.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

const std::filesystem::path kData = STRATA_TEST_DATA_DIR;

struct Camera {
  double lon, lat, altitude;
};

std::string observationPipeline(const std::string& observation, const Camera& camera) {
  return "strata: 1\n"
         "body: {name: Mars, radius: 3396190}\n"
         "camera: {lon: " +
         std::to_string(camera.lon) + ", lat: " + std::to_string(camera.lat) +
         ", altitude: " + std::to_string(camera.altitude) +
         ", fov: 45}\n"
         "nodes:\n"
         // Heights as grey levels, +-12 km (the planet's amplitude) to [0, 1]: a smooth field, so that what
         // differs between renderings is where the projections put it, not how each observation aliased
         // the colour map's one-texel contour lines.
         "  data: {type: source.gdal, path: " +
         (kData / (observation + "-height.tif")).string() +
         ", kind: luminance, scale: 4.1666666666666665e-05, offset: 0.5}\n"
         "  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [data], shading: none}\n";
}

// Where the strip observation has data: its alpha band, read whole (it is small), looked up by lon/lat.
class StripCoverage {
 public:
  StripCoverage() {
    GDALAllRegister();
    std::unique_ptr<GDALDataset> strip(GDALDataset::Open((kData / "strip-color.tif").c_str(), GDAL_OF_RASTER));
    if (!strip) return;
    strip->GetGeoTransform(transform_.data());
    width_ = strip->GetRasterXSize();
    height_ = strip->GetRasterYSize();
    alpha_.resize(std::size_t(width_) * height_);
    if (strip->GetRasterBand(4)->RasterIO(GF_Read, 0, 0, width_, height_, alpha_.data(), width_, height_, GDT_Byte, 0,
                                          0) != CE_None)
      alpha_.clear();
  }

  // Whether every texel within `margin` texels of (lon, lat) has data: away from the strip's feathered
  // and filtered edges.
  bool wellInside(double lon, double lat, int margin = 3) const {
    if (alpha_.empty()) return false;
    const int column = int(std::floor((lon - transform_[0]) / transform_[1]));
    const int row = int(std::floor((lat - transform_[3]) / transform_[5]));
    for (int y = row - margin; y <= row + margin; ++y)
      for (int x = column - margin; x <= column + margin; ++x)
        if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha_[std::size_t(y) * width_ + x] < 255) return false;
    return true;
  }

 private:
  std::array<double, 6> transform_{};
  int width_ = 0, height_ = 0;
  std::vector<unsigned char> alpha_;
};

struct Agreement {
  int judged = 0;
  double meanDifference = 0.0;  // levels of 255, over channels and judged pixels
  double farShare = 0.0;        // share of judged pixels with a channel more than kFar levels apart
};

// Far apart: more than 4 levels (about 380 m of height at 94 m a level), several times what the
// octaves finer than a texel (10 km) add to one observation and not another.
constexpr int kFar = 4;

Agreement compare(const Image& a, const Image& b, const View& view, double radius,
                  const std::function<bool(const SurfaceHit&)>& judged) {
  Agreement agreement;
  long far = 0;
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      auto hit = raycastSphere(view, radius, x, y);
      if (!hit || hit->incidence < 0.3 || !judged(*hit)) continue;
      const auto pa = a.at(x, y), pb = b.at(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        sum += std::abs(pa[c] - pb[c]);
        worst = std::max(worst, std::abs(pa[c] - pb[c]));
      }
      far += worst > kFar;
      ++agreement.judged;
    }
  if (agreement.judged) {
    agreement.meanDifference = sum / (3.0 * agreement.judged);
    agreement.farShare = double(far) / agreement.judged;
  }
  return agreement;
}

struct PairCase {
  const char* name;
  const char* first;
  const char* second;
  Camera camera;
  std::function<bool(const SurfaceHit&)> wellSampled;  // by both observations
};

// gtest names a case by its name rather than dumping its bytes.
void PrintTo(const PairCase& pair, std::ostream* out) { *out << pair.name; }

class ProjectionAgreement : public ::testing::TestWithParam<PairCase> {};

TEST_P(ProjectionAgreement, SamePictureWhereBothSampleWell) {
  const PairCase& pair = GetParam();
  ASSERT_TRUE(std::filesystem::exists(kData / "global-height.tif")) << "the test_data fixture did not run";
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const int size = 240;
  const Image first =
      renderFrame(*engine, directory.write("a.yaml", observationPipeline(pair.first, pair.camera)), size, size);
  const Image second =
      renderFrame(*engine, directory.write("b.yaml", observationPipeline(pair.second, pair.camera)), size, size);
  const View view = engine->view(size, size);
  const Agreement agreement = compare(first, second, view, engine->pipeline().body.radius, pair.wellSampled);
  std::cout << pair.first << " vs " << pair.second << ": " << agreement.judged << " pixels, mean difference "
            << agreement.meanDifference << " levels, " << 100.0 * agreement.farShare << "% beyond " << kFar << "\n";
  EXPECT_GT(agreement.judged, 2000) << "too few pixels were judged for the test to mean anything";
  // Tolerances. The observations sample one field at different texel sizes and shapes; on llvmpipe the
  // pairs agree to a mean of 0.07 to 0.28 levels, with at most 0.02% of pixels beyond kFar (next to the
  // pole, where HEALPix's polar triangles meet). Moving the HEALPix map by one texel (lon_0 = 0.2 degrees)
  // raises the mean against the global map to 0.46 levels, so 0.35 catches a projection misplaced by a
  // single texel.
  EXPECT_LT(agreement.meanDifference, 0.35);
  EXPECT_LT(agreement.farShare, 0.001);
}

bool lowLatitude(const SurfaceHit& hit) { return std::abs(hit.lat) <= 60.0; }

const StripCoverage& strip() {
  static const StripCoverage coverage;
  return coverage;
}

INSTANTIATE_TEST_SUITE_P(
    Observations, ProjectionAgreement,
    ::testing::Values(
        PairCase{"GlobalAndHealpix", "global", "healpix", {40.0, 10.0, 6e6}, lowLatitude},
        PairCase{"GlobalAndHealpixAcrossTheAntimeridian", "global", "healpix", {180.0, -20.0, 6e6}, lowLatitude},
        PairCase{"NorthCapAndHealpix",
                 "north",
                 "healpix",
                 {-60.0, 75.0, 6e6},
                 [](const SurfaceHit& h) { return h.lat >= 50.0; }},
        PairCase{"SouthCapAndHealpix",
                 "south",
                 "healpix",
                 {120.0, -75.0, 6e6},
                 [](const SurfaceHit& h) { return h.lat <= -50.0; }},
        PairCase{"GlobalAndNorthCap",
                 "global",
                 "north",
                 {0.0, 55.0, 4e6},
                 [](const SurfaceHit& h) { return h.lat >= 50.0 && h.lat <= 60.0; }},
        PairCase{"StripAndGlobal",
                 "strip",
                 "global",
                 {25.0, 20.0, 3e6},
                 [](const SurfaceHit& h) { return lowLatitude(h) && strip().wellInside(h.lon, h.lat); }}),
    [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace strata::test
