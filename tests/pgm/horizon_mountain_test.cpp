// A mountain behind the horizon rises above it ([Mahsman 2010, §3.3.2, §3.4.2, Figs. 3.14, 3.15, 3.22]; issue 5):
// 1 km above an Earth-sized sphere, whose horizon lies 113 km away, the view looks east along the equator
// at an 8 km peak 150 km away, 37 km beyond the horizon, which hides only its lowest 107 m. The grid's
// rays near the primary sphere's horizon turn onto the secondary sphere and sample the ground out to where
// the horizon ray leaves the highest sphere, 319 km further; without the secondary sphere the mesh would end
// at the horizon and the mountain would be cut off there, 24 pixels below its peak.
//
// The peak's place on the screen is exact, in double; the topmost pixel drawn in its column must lie
// within kPeakTolerance of it, and geometry.icosahedral and geometry.clipmap draw it alike (the clipmap's level
// holding the bare horizon, 156 km out, would reach the peak even without [Clasen & Hege 2006, §4.5]'s safety
// factor; tests/clipmap/drawn_levels_test.cpp judges the factor itself by lines of sight in double). Without the
// secondary sphere (zeta = 1) the same test sees the mountain cut off at the horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr double kEarth = 6371000.0;                            // m
constexpr double kPeakHeight = 8000.0, kPeakWidth = 20000.0;    // m: a Gaussian of this height and 1/e radius
const double kPeakLongitude = glm::degrees(150000.0 / kEarth);  // deg, on the equator
constexpr int kWidth = 320, kHeight = 240;
// Pixels: the peak is a smooth dome sampled by the grid (256 x 256 rays) and by the raster (556 m texels);
// a row either side of the true peak's pixel is what the two samplings may move its top.
constexpr double kPeakTolerance = 2.0;

// 340 x 340 texels of 0.005 degrees (556 m) around the peak.
void writeMountain(const std::filesystem::path& file) {
  constexpr double west = 0.5, north = 0.85, texel = 0.005;
  writeFloatRaster(file, 340, 340, {west, -north, west + 340 * texel, north}, [&](int column, int row) {
    const double lon = glm::radians(west + (column + 0.5) * texel - kPeakLongitude);
    const double lat = glm::radians(north - (row + 0.5) * texel);
    const double distance = kEarth * std::acos(std::cos(lat) * std::cos(lon));
    return float(kPeakHeight * std::exp(-(distance / kPeakWidth) * (distance / kPeakWidth)));
  });
}

std::string pipelineWith(const std::filesystem::path& mountain, const std::string& geometry) {
  return "strata: 1\nbody: {name: Earth, radius: " + std::to_string(kEarth) +
         "}\nnodes:\n"
         "  relief: {type: source.gdal, path: " +
         mountain.string() +
         ", kind: height}\n"
         "  terrain: {type: " +
         geometry + ", height: relief, lowest: 0, highest: " + std::to_string(kPeakHeight) +
         "}\n"
         "  frame: {type: output.image, geometry: terrain, shading: none}\n";
}

// The topmost pixel drawn in column x, or the image's height when none is.
int topmostDrawn(const Image& image, int x) {
  for (int y = 0; y < image.height; ++y)
    if (covered(image, x, y)) return y;
  return image.height;
}

// Where a planet-fixed point lands on the screen, in pixels from the top left (pixel centres at + 0.5).
glm::dvec2 projected(const View& view, const glm::dvec3& point) {
  const glm::dvec3 eye = view.toEye(point);
  const double focal = 0.5 * view.height / std::tan(0.5 * view.verticalFov);
  return {0.5 * view.width + focal * eye.x / -eye.z, 0.5 * view.height - focal * eye.y / -eye.z};
}

// Where the peak and the bare sphere's horizon land in the view, in pixels from the top.
struct Landmarks {
  glm::dvec2 peak;
  double horizon;
};

Landmarks landmarksOf(const View& view, double altitude) {
  const double horizonAngle = std::acos(kEarth / (kEarth + altitude));  // from the point below the eye
  return {projected(view, (kEarth + kPeakHeight) * unitNormal(glm::radians(kPeakLongitude), 0.0)),
          projected(view, kEarth * glm::dvec3(std::cos(horizonAngle), std::sin(horizonAngle), 0.0)).y};
}

class PgmHorizonMountain : public ::testing::Test {
 protected:
  // The topmost row drawn in the peak's column by `geometry` (its YAML after the type).
  int topOfThePeak(const std::string& geometry) {
    engine_->load(directory_.write("mountain.yaml", pipelineWith(directory_.path() / "mountain.tif", geometry)));
    const int top = topmostDrawn(renderFrames(*engine_, kCamera, kWidth, kHeight, 3), int(landmarks_.peak.x));
    std::printf("%s: the peak's top at row %d, the true peak at %.1f, the bare horizon at %.1f\n", geometry.c_str(),
                top, landmarks_.peak.y, landmarks_.horizon);
    return top;
  }

  static inline const Camera kCamera{
      .lon = 0.0, .lat = 0.0, .altitude = 1000.0, .heading = 90.0, .tilt = 89.0, .fov = 30.0};
  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_ = makeEngine();
  Landmarks landmarks_ =
      landmarksOf(makeView(Body{.name = "Earth", .radius = kEarth}, kCamera, kWidth, kHeight), kCamera.altitude);
  void SetUp() override {
    writeMountain(directory_.path() / "mountain.tif");
    // The peak stands well above the bare horizon, or the test shows nothing.
    ASSERT_LT(landmarks_.peak.y, landmarks_.horizon - 20.0);
  }
};

TEST_F(PgmHorizonMountain, AMountainBehindTheHorizonIsDrawnToItsPeak) {
  for (const std::string geometry : {"geometry.pgm", "geometry.icosahedral", "geometry.clipmap"})
    EXPECT_NEAR(topOfThePeak(geometry) + 0.5, landmarks_.peak.y, kPeakTolerance) << geometry;
}

// With zeta = 1 the blend towards the secondary sphere never starts (b = tau0): the mesh ends at the
// primary sphere's horizon and only the mountain's foot in front of it shows, as in the thesis's Fig. 3.14.
TEST_F(PgmHorizonMountain, WithoutTheSecondarySphereTheMountainIsCutOff) {
  EXPECT_GT(topOfThePeak("geometry.pgm, zeta: 1") + 0.5, landmarks_.horizon - 4.0);
}

}  // namespace
}  // namespace strata::test
