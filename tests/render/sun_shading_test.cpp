// output.image's shading by the scene's sun: the light and the terminator where the subsolar point puts
// them, the twilight's width as declared, night layers on the night side only, the Earth's sun from the
// date, and the refusals where the scene places no sun.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <strata/sun.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 256;
constexpr double kAmbient = 0.5, kTwilight = 6.0;  // deg

// 8-bit levels: the frame's quantisation (half a level) and the sphere normal the deferred buffer rebuilds
// from float longitude and latitude, whose error moves the light by under a level even within the twilight,
// where it changes fastest (16 levels a pixel here).
constexpr int kLevels = 3;

// 20,000 km over longitude -60 on the equator: over the terminator of a sun over 30 east.
const char* const kOverTheTerminator = "{lon: -60, lat: 0, altitude: 2.0e7, fov: 40}";

// A white Earth seen by `camera`, lit by the sun `scene` places, with a
// red night layer; linear light read as it is (view: Raw).
std::string sunlitEarth(const std::filesystem::path& white, const std::filesystem::path& red, const std::string& scene,
                        const std::string& camera = kOverTheTerminator) {
  return "strata: 1\n" + scene + "\ncamera: " + camera +
         "\n"
         "nodes:\n"
         "  white: {type: source.gdal, path: '" +
         white.string() + "', kind: color}\n  red: {type: source.gdal, path: '" + red.string() +
         "', kind: color}\n"
         "  terrain: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: terrain, surface: [white], night: [red], shading: sun, "
         "ambient: 0.5, twilight: 6, antialiasing: none, view: Raw}\n";
}

class SunShading : public ::testing::Test {
 protected:
  void SetUp() override {
    writeColourRaster(white_, 64, 32, {-180.0, -90.0, 180.0, 90.0}, [](int, int) { return Rgb8{255, 255, 255}; });
    writeColourRaster(red_, 64, 32, {-180.0, -90.0, 180.0, 90.0}, [](int, int) { return Rgb8{255, 0, 0}; });
  }

  Image render(const std::string& scene, View* view = nullptr, const std::string& camera = kOverTheTerminator) {
    auto engine = makeEngine();
    const Image image =
        renderFrame(*engine, directory_.write("sun.yaml", sunlitEarth(white_, red_, scene, camera)), kSize, kSize);
    if (view) *view = engine->view(kSize, kSize);
    return image;
  }

  // The light the model gives at a point whose direction from the centre makes cos `toSun` with the sun's:
  // ambient by day, fading through the twilight, plus Lambert's direct light (composite.frag).
  static double daylight(double toSun) {
    const double edge = std::sin(glm::radians(kTwilight)), t = std::clamp((toSun + edge) / edge, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
  }

  // Every pixel of row `y` on the body: its green (white lit, red unlit) is the model's light, and its red adds
  // the night layer by what the day leaves. Counts the pixels by day, in the twilight and by night.
  std::array<int, 3> judgeRow(const Image& image, const View& view, const glm::dvec3& sun, int y,
                              int levels = kLevels) const {
    std::array<int, 3> counts{};
    for (int x = 0; x < kSize; ++x) {
      const auto hit = raycastSphere(view, 6371000.0, x, y);
      if (!hit) continue;
      const double toSun = glm::dot(unitNormal(glm::radians(hit->lon), glm::radians(hit->lat)), sun);
      const double light = kAmbient * daylight(toSun) + (1.0 - kAmbient) * std::max(toSun, 0.0);
      const std::array<int, 4> pixel = image.at(x, y);
      EXPECT_NEAR(pixel[1], 255.0 * light, levels) << "x " << x << ", lon " << hit->lon << ", lat " << hit->lat;
      EXPECT_NEAR(pixel[0], std::min(255.0 * (light + 1.0 - daylight(toSun)), 255.0), levels) << "x " << x;
      counts[toSun > 0.0 ? 0 : toSun < -std::sin(glm::radians(kTwilight)) ? 2 : 1] += 1;
    }
    return counts;
  }

  TemporaryDirectory directory_;
  std::filesystem::path white_ = directory_.path() / "white.tif", red_ = directory_.path() / "red.tif";
};

// Along the equator, from the day side across the terminator (at longitude -60 for a sun over 30 east) into
// the night: the light is the model's at every pixel.
TEST_F(SunShading, TheTerminatorAndTheTwilightLieWhereTheSunSays) {
  View view;
  const Image image = render("sun: {lon: 30, lat: 0}", &view);
  const auto [day, twilight, night] = judgeRow(image, view, sunDirection({30.0, 0.0}), kSize / 2);
  EXPECT_GT(day, 20);
  EXPECT_GT(twilight, 5);  // the terminator's width is resolved, not a step
  EXPECT_GT(night, 20);
}

// The terminator along the antimeridian (a sun over 90 east), seen from over longitude 180: the light the
// model gives on both sides of the meridian where longitudes wrap.
TEST_F(SunShading, TheTerminatorAcrossTheAntimeridian) {
  View view;
  const Image image = render("sun: {lon: 90, lat: 0}", &view, "{lon: 180, lat: 20, altitude: 2.0e7, fov: 40}");
  const auto [day, twilight, night] = judgeRow(image, view, sunDirection({90.0, 0.0}), kSize / 2);
  EXPECT_GT(day, 20);
  EXPECT_GT(twilight, 5);
  EXPECT_GT(night, 20);
}

// Over the north pole with the sun on the equator at 90 east, the terminator runs through the pole, where
// every meridian meets, along longitudes 0 and 180: rows across the frame run from day into night. Within 6
// levels: 2 degrees from the pole the deferred buffer's longitude, interpolated linearly across a triangle
// whose corners' longitudes differ by tens of degrees there, places the point up to a third of a pixel off
// the sphere's, which the twilight's 16 levels a pixel turn into 5.
TEST_F(SunShading, TheTerminatorThroughThePole) {
  constexpr int kPolarLevels = 6;
  View view;
  const Image image = render("sun: {lon: 90, lat: 0}", &view, "{lon: 0, lat: 90, altitude: 2.0e7, fov: 40}");
  for (const int y : {kSize / 2, kSize / 3}) {
    const auto [day, twilight, night] = judgeRow(image, view, sunDirection({90.0, 0.0}), y, kPolarLevels);
    EXPECT_GT(day, 20);
    EXPECT_GT(night, 20);
    EXPECT_GT(twilight, 2);
  }
}

// From 100 km up over the terminator the frame spans a third of a degree of the twilight's six: the light the
// model gives, pixel by pixel, as the sun sinks across the frame.
TEST_F(SunShading, TheTwilightFromCloseBy) {
  View view;
  const Image image = render("sun: {lon: 30, lat: 0}", &view, "{lon: -61, lat: 0, altitude: 1.0e5, fov: 40}");
  const auto [day, twilight, night] = judgeRow(image, view, sunDirection({30.0, 0.0}), kSize / 2);
  EXPECT_EQ(twilight, kSize);
  EXPECT_NE(image.at(0, kSize / 2)[1], image.at(kSize - 1, kSize / 2)[1]);  // the light changes across it
}

// The Earth's sun from the scene's date: the same frame as the subsolar point the almanac's formulas give.
TEST_F(SunShading, TheDatePlacesTheEarthsSun) {
  const SubsolarPoint sun = earthSubsolarPoint(*parseIsoDate("2024-06-20T20:51Z"));
  const Image byDate = render("date: 2024-06-20T20:51Z");
  const Image fixed = render("sun: {lon: " + std::to_string(sun.lon) + ", lat: " + std::to_string(sun.lat) + "}");
  int differing = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) differing += std::abs(byDate.at(x, y)[c] - fixed.at(x, y)[c]) > 1;
  EXPECT_EQ(differing, 0);  // std::to_string keeps six decimals: 1e-6 degrees, far below a level
}

std::string loadError(TemporaryDirectory& directory, const std::string& pipeline) {
  auto engine = makeEngine();
  try {
    engine->load(directory.write("p.yaml", pipeline));
  } catch (const Error& error) {
    return error.problem() + " | " + error.fix();
  }
  return "";
}

TEST_F(SunShading, WithoutADateOrASunTheSunsShadingIsRefused) {
  const std::string error = loadError(directory_, sunlitEarth(white_, red_, "body: {name: Earth}"));
  EXPECT_NE(error.find("shading: sun, but the scene does not say where the sun is"), std::string::npos) << error;
  EXPECT_NE(error.find("date: 2024-03-20T12:00"), std::string::npos) << error;
  // Mars has a date but no motion Strata knows: its sun must be given.
  EXPECT_NE(loadError(directory_, sunlitEarth(white_, red_, "body: {name: Mars}\ndate: 2024-03-20")).find("sun: {lon"),
            std::string::npos);
}

TEST_F(SunShading, NightLayersNeedTheSunsShading) {
  std::string pipeline = sunlitEarth(white_, red_, "sun: {lon: 0, lat: 0}");
  pipeline.replace(pipeline.find("shading: sun"), 12, "shading: lambert");
  EXPECT_NE(loadError(directory_, pipeline).find("night layers are given"), std::string::npos);
}

}  // namespace
}  // namespace strata::test
