// The Earth's air drawn by output.image (shaders/strata/atmosphere.glsl) against the same model summed in double
// (airLightAlong, 500 segments and the sun's transmittance by quadrature): the sky from the ground by day and at
// sunset, and the limb and the haze over the ground from orbit; and the refusal of an air no sun lights.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <strata/atmosphere_tables.hpp>
#include <strata/error.hpp>
#include <strata/sun.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 128;
constexpr double kRadius = 6371000.0;
constexpr double kGrey = 0.18;  // output.image's colour where no layer has data, unlit (shading: none)

// 8-bit levels between the frame and the model in double: half a level of quantisation, and what 32 segments
// along a ray, the tables' bilinear reading and float leave (1.7 levels at worst in these frames).
constexpr double kLevels = 2.5;

// The grey bare Earth under the sun over (`sunLon`, `sunLat`), with the Earth's air, seen by `camera`; linear light.
std::string airyEarth(double sunLon, const std::string& camera, double sunLat = 0.0) {
  return "strata: 1\nsun: {lon: " + std::to_string(sunLon) + ", lat: " + std::to_string(sunLat) +
         "}\natmosphere: {}\ncamera: " + camera +
         "\nnodes:\n  terrain: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: terrain, shading: none, antialiasing: none, view: Raw}\n";
}

class AtmosphereRendering : public ::testing::Test {
 protected:
  // Renders the scene and compares every 8th pixel with the model: grey ground dimmed by the air before it, and
  // the air's light, pi times its radiance for a sun of 1 (composite.frag's throughAir). Returns the frame.
  Image renderAndJudge(double sunLon, const std::string& camera, double sunLat = 0.0) {
    auto engine = makeEngine();
    const Image image =
        renderFrame(*engine, directory_.write("air.yaml", airyEarth(sunLon, camera, sunLat)), kSize, kSize);
    view_ = engine->view(kSize, kSize);
    const View& view = view_;
    const glm::dvec3 sun = sunDirection({sunLon, sunLat});
    for (int y = 4; y < kSize; y += 8)
      for (int x = 4; x < kSize; x += 8) {
        const glm::dvec3 expected = 255.0 * modelled(view, sun, x, y);
        const std::array<int, 4> pixel = image.at(x, y);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(pixel[c], std::min(expected[c], 255.0), kLevels)
              << "pixel " << x << ", " << y << " channel " << c;
      }
    return image;
  }

  // The light the model gives pixel (x, y): the ground's grey through the air, and the air's own.
  glm::dvec3 modelled(const View& view, const glm::dvec3& sun, int x, int y) const {
    const glm::dvec2 half = view.halfFrameTangents();
    const glm::dvec3 inEye((2.0 * (x + 0.5) / view.width - 1.0) * half.x,
                           (1.0 - 2.0 * (y + 0.5) / view.height) * half.y, -1.0);
    const glm::dvec3 direction = glm::normalize(glm::transpose(view.planetToEye) * inEye);
    const auto hit = raycastSphere(view, kRadius, x, y);
    const AirLight air = airLightAlong(model_, tables_, view.eye, direction, hit ? hit->distance : 1e30, sun, 500, 100);
    return (hit ? kGrey : 0.0) * air.transmittance + glm::pi<double>() * air.inscattered;
  }

  TemporaryDirectory directory_;
  View view_;  // the last frame's
  AtmosphereModel model_{Atmosphere{}, kRadius};
  AtmosphereTables tables_ = makeAtmosphereTables(model_);
};

// From 100 m up, looking east 10 degrees below the horizon at 9 in the morning (the sun 30 degrees high in the
// east): the sky above the horizon, the ground hazier with distance below it.
TEST_F(AtmosphereRendering, TheSkyFromTheGround) {
  const Image image = renderAndJudge(60.0, "{lon: 0, lat: 0, altitude: 100, heading: 90, tilt: 80, fov: 60}");
  const std::array<int, 4> high = image.at(kSize / 2, 2);
  EXPECT_GT(high[2], high[0]);  // blue
}

// Looking west along the ground as the sun sets behind the eye, and east as it sets before it: red over the
// horizon toward the sun.
TEST_F(AtmosphereRendering, TheSkyAtSunset) {
  const Image image = renderAndJudge(88.0, "{lon: 0, lat: 0, altitude: 100, heading: 90, tilt: 88, fov: 40}");
  const std::array<int, 4> horizon = image.at(kSize / 2, kSize / 2 - 8);
  EXPECT_GT(horizon[0], horizon[2]);
}

// From 400 km up, looking east at the horizon under a sun 45 degrees high there: a thin blue glow above the
// limb, the air 60 km thick seen edge-on from 2,300 km (about six pixels), and haze over the ground.
TEST_F(AtmosphereRendering, TheLimbFromOrbit) {
  const Image image = renderAndJudge(45.0, "{lon: 0, lat: 0, altitude: 4.0e5, heading: 90, tilt: 72, fov: 30}");
  int glowing = 0;
  for (int y = 0; y < kSize; ++y) {
    const std::array<int, 4> pixel = image.at(kSize / 2, y);
    if (!raycastSphere(view_, kRadius, kSize / 2, y) && pixel[2] > 10 && pixel[2] > pixel[0]) ++glowing;
  }
  EXPECT_GE(glowing, 3);
}

// Half a degree from the north pole, looking across it toward a sun 20 degrees up: the air's geometry is
// planet-fixed positions, which meet no seam at the pole.
TEST_F(AtmosphereRendering, TheSkyOverThePole) {
  renderAndJudge(0.0, "{lon: 180, lat: 89.5, altitude: 100, heading: 0, tilt: 80, fov: 60}", 20.0);
}

// The limb from 400 km over the antimeridian, looking east across it toward a sun 45 degrees high there.
TEST_F(AtmosphereRendering, TheLimbAcrossTheAntimeridian) {
  renderAndJudge(-135.0, "{lon: 179, lat: 0, altitude: 4.0e5, heading: 90, tilt: 72, fov: 30}");
}

// The same view in a scene of several bodies (the Moon far out of view): the Earth's frame laid over space shows
// the air's glow beyond its limb as its own pipeline alone does, within a level.
TEST_F(AtmosphereRendering, TheLimbGlowsInASceneOfSeveralBodies) {
  const std::string camera = "{lon: 0, lat: 0, altitude: 4.0e5, heading: 90, tilt: 72, fov: 30}";
  auto engine = makeEngine();
  const Image alone = renderFrame(*engine, directory_.write("earth.yaml", airyEarth(45.0, camera)), kSize, kSize);
  directory_.write("moon.yaml",
                   "strata: 1\nbody: {name: Moon}\nnodes:\n  terrain: {type: geometry.icosahedral}\n"
                   "  frame: {type: output.image, geometry: terrain, antialiasing: none, view: Raw}\n");
  const Image scene =
      renderFrame(*makeEngine(),
                  directory_.write("scene.yaml", "strata: 1\nsun: {lon: 45, lat: 0}\ncamera: " + camera +
                                                     "\nbodies:\n  earth: {pipeline: earth.yaml}\n"
                                                     "  moon: {pipeline: moon.yaml, position: [0, 0, "
                                                     "-3.844e8]}\n"),
                  kSize, kSize);
  int glowing = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(scene.at(kSize / 2, y)[c], alone.at(kSize / 2, y)[c], 1) << "row " << y;
    if (alone.at(kSize / 2, y)[2] > 10 && !raycastSphere(engine->view(kSize, kSize), kRadius, kSize / 2, y)) ++glowing;
  }
  EXPECT_GE(glowing, 3);
}

// From 2.6 million km (400 radii of the air's top), where float would draw the air wrong, the body is drawn
// airless (docs/atmosphere.md, "Limits"): the frame is the one without `atmosphere:`.
TEST_F(AtmosphereRendering, FromFarBeyondTheAirTheBodyIsDrawnAirless) {
  const std::string camera = "{lon: 0, lat: 0, altitude: 2.6e9, fov: 0.5}";
  std::string airless = airyEarth(45.0, camera);
  airless.erase(airless.find("atmosphere: {}\n"), std::string("atmosphere: {}\n").size());
  const Image far = renderFrame(*makeEngine(), directory_.write("far.yaml", airyEarth(45.0, camera)), kSize, kSize);
  const Image without = renderFrame(*makeEngine(), directory_.write("airless.yaml", airless), kSize, kSize);
  EXPECT_EQ(far.rgba, without.rgba);
  EXPECT_TRUE(covered(far, kSize / 2, kSize / 2));
}

// An atmosphere with neither a date nor a sun: refused at the section, with the fix.
TEST_F(AtmosphereRendering, AnAirNoSunLightsIsRefused) {
  auto engine = makeEngine();
  const std::string pipeline =
      "strata: 1\natmosphere: {}\nnodes:\n  terrain: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: terrain}\n";
  try {
    renderFrame(*engine, directory_.write("dark.yaml", pipeline), kSize, kSize);
    FAIL() << "an atmosphere without a sun was drawn";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("dark.yaml:2"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("sun"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace strata::test
