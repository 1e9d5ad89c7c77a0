// composite.relief (issue 8; [Kooima 2008, §1.1], relief shading): the shade of a synthetic cone against the
// analytic Lambert shading of its exact normal; and output.image's normal maps, of the same cone's normals.
//
// The cone: height H (1 - r / R) up to r = R about (0, 0) on Mars, H = 20 km, R = 1 degree (59.3 km), so its
// flank rises at H / R = 0.337 (18.6 degrees); a Float32 raster of 1024 x 1024 texels over 2.4 x 2.4 degrees
// (139 m a texel), r measured along the ground as the test reckons it. Seen straight down from 160 km with
// output.image's shading off (the globe is the undisplaced sphere), a pixel spans some 0.5 km, 4 texels:
// each pixel's value is the relief layer's shade where the exact ray-sphere intersection (in double) lands.
// The flank's exact normal there is normalize((H / R) r_hat, 1) in east/north/up, and the analytic shade is
// max(0, n . l) for the light l at the azimuth and altitude.
//
// Judged: pixels on the flank between 0.2 R and 0.8 R, several kilometres from the apex and the rim, whose
// creases the footprint rounds off. The slopes are the central differences of the texels of the pyramid level the
// footprint picks (4 texels a pixel: level 2, 556 m texels), mixed across the texel cell (SlopedLayer).
// Tolerance, in 8-bit levels of the sRGB-encoded frame: 0.5 for quantisation, plus the gradient's error. On
// a plane both the central differences and bilinear filtering are exact; the cone's curvature across its
// radius (H / (R r), at most 2.8e-5 / m at 0.2 R) turns the gradient by under 1e-3 rad over a pixel, and the
// heights (float, about 2 mm at 20 km) rise 370 m over the difference's 1.1 km, a 1e-5 error: together under
// 0.2 levels (a level is some 0.004 of the shade there). So 1 level. Measured on llvmpipe: at most 0.50
// levels (a mean of 0.24) for azimuths 0, 90, 225 and 315 at altitude 45; 0.56 for exaggeration 2 under a
// light at 30 degrees (2.2 with the gradient of each texel cell's bilinear patch, which jumps at its edges, and
// 0.77 with central differences of samples a footprint apart); 0.56 multiplied over a surface, 0.50 alone; 0.50
// multidirectional (Mark's four lights); 0.41 for the slope and 0.50 for the aspect (output: slope, aspect);
// normalised 0.50; tinted by elevation 0.50, by slope 0.50; the same tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>
#include <strata/error.hpp>
#include <strata/sun.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 240;
constexpr double kRadius = 3396190.0;  // m, Mars
constexpr double kConeHeight = 20000.0;
constexpr double kConeDegrees = 1.0;
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kConeRadius = kConeDegrees * kDegree * kRadius;  // m along the ground
constexpr int kTexels = 1024;
constexpr double kHalfExtent = 1.2;  // deg

// East and north of the apex at (0, 0), m along the ground.
struct Offset {
  double east, north;
  double length() const { return std::hypot(east, north); }
};
Offset offsetOf(double lonDegrees, double latDegrees) {
  return {kRadius * lonDegrees * kDegree * std::cos(latDegrees * kDegree), kRadius * latDegrees * kDegree};
}

double coneHeight(Offset o) { return kConeHeight * std::max(0.0, 1.0 - o.length() / kConeRadius); }

void writeCone(const std::filesystem::path& file) {
  const double texel = 2.0 * kHalfExtent / kTexels;
  writeFloatRaster(
      file, kTexels, kTexels, {-kHalfExtent, -kHalfExtent, kHalfExtent, kHalfExtent}, [&](int column, int row) {
        return float(coneHeight(offsetOf(-kHalfExtent + (column + 0.5) * texel, kHalfExtent - (row + 0.5) * texel)));
      });
}

// Lambert's cosine of the flank's exact normal at `o`, its slope H / R times `exaggeration`, with the light
// at azimuth and altitude (degrees).
double analyticShade(Offset o, double azimuth, double altitude, double exaggeration = 1.0) {
  const double slope = exaggeration * kConeHeight / kConeRadius, r = o.length();
  const double nx = slope * o.east / r, ny = slope * o.north / r, nz = 1.0, n = std::sqrt(nx * nx + ny * ny + nz * nz);
  const double lx = std::sin(azimuth * kDegree) * std::cos(altitude * kDegree),
               ly = std::cos(azimuth * kDegree) * std::cos(altitude * kDegree), lz = std::sin(altitude * kDegree);
  return std::max(0.0, (nx * lx + ny * ly + nz * lz) / n);
}

// The sRGB encoding output.image writes (its default display, sRGB, view Standard: docs/colour.md), in 8-bit
// levels.
double srgbLevel(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

// The cone's relief with `relief` said of it, over `more` nodes (a surface), as the frame's one surface.
std::string pipeline(const std::filesystem::path& cone, const std::string& relief, const std::string& more = "") {
  return "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
         "camera: {lon: 0, lat: 0, altitude: 1.6e5, fov: 45}\n"
         "nodes:\n"
         "  cone: {type: source.gdal, path: " +
         cone.string() + ", kind: height}\n" + more + "  relief: {type: composite.relief, height: cone" + relief +
         "}\n"
         "  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [relief], shading: none}\n";
}

struct Agreement {
  int judged = 0;
  double largest = 0.0;  // levels
  double mean = 0.0;
};

class Relief : public ::testing::Test {
 protected:
  void SetUp() override { writeCone(file("cone.tif")); }

  Agreement normalMapped(bool objectSpace);

  std::filesystem::path file(const std::string& name) const { return directory_.path() / name; }

  // The red channel of the frame of `text` against `expected`(offset from the apex) in levels, on the flank
  // (where `expected` is negative, not judged).
  template <class Expected>
  Agreement compare(const std::string& what, const std::string& text, Expected expected) {
    const Image image = renderFrame(*engine_, directory_.write("relief.yaml", text), kSize, kSize);
    const View view = makeView(engine_->pipeline().body, engine_->camera(), kSize, kSize);
    Agreement agreement;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto hit = raycastSphere(view, kRadius, x, y);
        if (!hit) continue;
        const Offset o = offsetOf(hit->lon, hit->lat);
        if (o.length() < 0.2 * kConeRadius || o.length() > 0.8 * kConeRadius) continue;
        const double level = expected(o);
        if (level < 0.0) continue;  // not judged
        const double error = std::abs(image.at(x, y)[0] - level);
        agreement.largest = std::max(agreement.largest, error);
        agreement.mean += error;
        ++agreement.judged;
      }
    agreement.mean /= std::max(agreement.judged, 1);
    std::printf("%s: %d pixels, largest difference %.2f levels, mean %.2f\n", what.c_str(), agreement.judged,
                agreement.largest, agreement.mean);
    return agreement;
  }

  TemporaryDirectory directory_;
  std::unique_ptr<Engine> engine_ = makeEngine();
};

TEST_F(Relief, ConeMatchesAnalyticLambertShadingAtSeveralAzimuths) {
  for (const double azimuth : {0.0, 90.0, 225.0, 315.0}) {
    const std::string relief = ", azimuth: " + std::to_string(azimuth);
    const Agreement agreement = compare("azimuth " + std::to_string(azimuth), pipeline(file("cone.tif"), relief),
                                        [&](Offset o) { return srgbLevel(analyticShade(o, azimuth, 45.0)); });
    EXPECT_GT(agreement.judged, 10000) << "the flank covers much of the frame";
    EXPECT_LE(agreement.largest, 1.0) << "azimuth " << azimuth;
  }
}

TEST_F(Relief, ExaggerationAndAltitudeShadeAsASteeperConeUnderALowerLight) {
  const Agreement agreement =
      compare("exaggeration 2, altitude 30", pipeline(file("cone.tif"), ", exaggeration: 2, altitude: 30"),
              [](Offset o) { return srgbLevel(analyticShade(o, 315.0, 30.0, 2.0)); });
  EXPECT_LE(agreement.largest, 1.0);
}

// Normalised, the shade is Lambert's over flat ground's, sin(altitude): brighter than 1 on the flank facing
// the light (white, once encoded) and the surface's own colour on flat ground.
TEST_F(Relief, NormalisedTheShadeIsOverFlatGrounds) {
  const Agreement agreement = compare("normalised", pipeline(file("cone.tif"), ", normalise: true"), [](Offset o) {
    return srgbLevel(analyticShade(o, 315.0, 45.0) / std::sin(45.0 * kDegree));
  });
  EXPECT_LE(agreement.largest, 1.0);
}

// Under the sun the light is the sun's direction in each point's own east/north/up frame: a sun over (-45, 10)
// stands west and a little north of the cone, higher over its western flank, and the shade follows it point by
// point. The same tolerance as for a fixed light.
// The shade of the cone's exact normal at `o` under the sun over (-45, 10), as it stands over that point: its
// azimuth and altitude in the ground's own east/north/up frame.
double shadeUnderTheSun(Offset o) {
  const glm::dvec3 sun = sunDirection({-45.0, 10.0});
  const double lon = o.east / (kRadius * std::cos(o.north / kRadius)) / kDegree, lat = o.north / kRadius / kDegree;
  const glm::dvec3 up = unitNormal(lon * kDegree, lat * kDegree);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), up)), north = glm::cross(up, east);
  const double altitude = std::asin(glm::dot(sun, up)) / kDegree;
  const double azimuth = std::atan2(glm::dot(sun, east), glm::dot(sun, north)) / kDegree;
  return analyticShade(o, azimuth, altitude);
}

TEST_F(Relief, UnderTheSunEachPointIsLitAsTheSunStandsOverIt) {
  std::string text = pipeline(file("cone.tif"), ", light: sun");
  text.replace(text.find("camera:"), 0, "sun: {lon: -45, lat: 10}\n");
  const Agreement agreement = compare("sun", text, [](Offset o) { return srgbLevel(shadeUnderTheSun(o)); });
  EXPECT_GT(agreement.judged, 10000);
  EXPECT_LE(agreement.largest, 1.0);
}

// A normal map of the cone's exact normals (16-bit, of the cone's raster's size and extent) over a white surface
// on the bare sphere, lit by the sun with no ambient light: its frame and how it was judged against the analytic
// shade. `objectSpace`: each normal turned into the planet-fixed axes at its texel (normal_space: object).
Agreement Relief::normalMapped(bool objectSpace) {
  const double texel = 2.0 * kHalfExtent / kTexels;
  const std::array<double, 4> extent{-kHalfExtent, -kHalfExtent, kHalfExtent, kHalfExtent};
  writeColourRaster16(file("normals.tif"), kTexels, kTexels, extent, [&](int column, int row) {
    const double lon = -kHalfExtent + (column + 0.5) * texel, lat = kHalfExtent - (row + 0.5) * texel;
    const Offset o = offsetOf(lon, lat);
    const double r = o.length(), slope = r < kConeRadius ? kConeHeight / kConeRadius : 0.0;
    glm::dvec3 n = glm::normalize(glm::dvec3(slope * o.east / r, slope * o.north / r, 1.0));
    if (objectSpace) n = glm::transpose(planetToLocal({lon * kDegree, lat * kDegree})) * n;
    const auto encoded = [](double c) { return std::uint16_t(std::lround((0.5 * c + 0.5) * 65535.0)); };
    return Rgb16{encoded(n.x), encoded(n.y), encoded(n.z)};
  });
  writeColourRaster(file("white.tif"), 8, 8, extent, [](int, int) { return Rgb8{255, 255, 255}; });
  const std::string text =
      "strata: 1\nbody: {name: Mars, radius: 3396190}\nsun: {lon: -45, lat: 10}\n"
      "camera: {lon: 0, lat: 0, altitude: 1.6e5, fov: 45}\n"
      "nodes:\n"
      "  white: {type: source.gdal, path: " +
      file("white.tif").string() +
      ", kind: color}\n  normals: {type: source.gdal, path: " + file("normals.tif").string() +
      ", kind: normal, normal_space: " + (objectSpace ? "object" : "tangent") +
      "}\n"
      "  globe: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: globe, surface: [white], normal: [normals], "
      "shading: sun, ambient: 0}\n";
  return compare("normal map", text, [](Offset o) { return srgbLevel(shadeUnderTheSun(o)); });
}

// output.image's normal maps: a tangent-space map shades as its analytic normals do. Half-float pages keep a
// normal's components to 0.0005, and the mip levels' averaged normals, renormalised, turn by under 1e-4 rad on
// the judged flank: the relief's tolerance holds.
TEST_F(Relief, ANormalMapShadesAsItsAnalyticNormals) {
  const Agreement agreement = normalMapped(false);
  EXPECT_GT(agreement.judged, 10000);
  EXPECT_LE(agreement.largest, 1.0);
}

// The same normals given in the body's planet-fixed axes (normal_space: object) shade alike: the layer turns
// each into the ground's frame where it is sampled. Filtering blends them in planet-fixed axes, where
// neighbouring texels' normals differ by the texel's 0.0024 degrees more than in the ground's frame: nothing
// at the tolerance.
TEST_F(Relief, AnObjectSpaceNormalMapShadesAsItsAnalyticNormals) {
  const Agreement agreement = normalMapped(true);
  EXPECT_GT(agreement.judged, 10000);
  EXPECT_LE(agreement.largest, 1.0);
}

// The shade is light already (Layer::shaded): output.image's own light (shading: lambert, from the upper left)
// does not shade it a second time, so the frame is the analytic shade as with shading: none.
TEST_F(Relief, TheOutputsLightDoesNotShadeTheReliefAgain) {
  std::string text = pipeline(file("cone.tif"), "");
  text.replace(text.find("shading: none"), 13, "shading: lambert");
  const Agreement agreement =
      compare("lit output", text, [](Offset o) { return srgbLevel(analyticShade(o, 315.0, 45.0)); });
  EXPECT_GT(agreement.judged, 10000);
  EXPECT_LE(agreement.largest, 1.0);
}

TEST_F(Relief, TheSunsLightNeedsTheScenesSun) {
  try {
    renderFrame(*engine_, directory_.write("relief.yaml", pipeline(file("cone.tif"), ", light: sun")), 16, 16);
    FAIL() << "loaded without a sun";
  } catch (const Error& error) {
    EXPECT_EQ(error.problem(), "light: sun, but the scene does not say where the sun is");
  }
}

// Mark's multidirectional shading (USGS Open-File Report 92-422) of the exact normal: lights at 225, 270,
// 315 and 360 degrees, each weighted by sin^2(aspect - azimuth), the aspect the compass direction away from
// the apex, halved (the weights sum to 2).
double analyticMultidirectional(Offset o, double altitude) {
  const double aspect = std::atan2(o.east, o.north) / kDegree;
  double sum = 0.0;
  for (const double azimuth : {225.0, 270.0, 315.0, 360.0}) {
    const double oblique = std::sin((aspect - azimuth) * kDegree);
    sum += oblique * oblique * analyticShade(o, azimuth, altitude);
  }
  return 0.5 * sum;
}

TEST_F(Relief, MultidirectionalMatchesMarksWeightedLights) {
  const Agreement agreement =
      compare("multidirectional", pipeline(file("cone.tif"), ", mode: multidirectional, altitude: 40"),
              [](Offset o) { return srgbLevel(analyticMultidirectional(o, 40.0)); });
  EXPECT_LE(agreement.largest, 1.0);
}

// The slope is the flank's everywhere, atan(H / R) over 90 degrees; the aspect the direction away from the
// apex over 360 degrees, judged away from north, where it wraps from 1 to 0 within a pixel.
TEST_F(Relief, SlopeAndAspectAreTheFlanks) {
  const double slope = std::atan(kConeHeight / kConeRadius) / (0.5 * std::numbers::pi);
  const Agreement slopes =
      compare("slope", pipeline(file("cone.tif"), ", output: slope"), [&](Offset) { return srgbLevel(slope); });
  EXPECT_LE(slopes.largest, 1.0);
  const Agreement aspects = compare("aspect", pipeline(file("cone.tif"), ", output: aspect"), [](Offset o) {
    const double aspect = std::atan2(o.east, o.north) / kDegree;
    if (std::abs(aspect) < 10.0) return -1.0;  // near north: not judged
    return srgbLevel((aspect < 0.0 ? aspect + 360.0 : aspect) / 360.0);
  });
  EXPECT_LE(aspects.largest, 1.0);
}

// Over a surface of one colour the shade multiplies it (in scene-linear light); `blend: alone` gives the grey
// shade whatever the surface.
TEST_F(Relief, MultipliesASurfaceOrShadesAlone) {
  constexpr unsigned char kLevel = 200;  // sRGB; 0.578 linear
  writeColourRaster(file("paint.tif"), 8, 8, {-kHalfExtent, -kHalfExtent, kHalfExtent, kHalfExtent}, [](int, int) {
    return Rgb8{kLevel, kLevel, kLevel};
  });
  const std::string paint = "  paint: {type: source.gdal, path: " + file("paint.tif").string() + ", kind: color}\n";
  const double linear = std::pow((kLevel / 255.0 + 0.055) / 1.055, 2.4);
  const Agreement multiplied = compare("multiply", pipeline(file("cone.tif"), ", surface: paint", paint),
                                       [&](Offset o) { return srgbLevel(linear * analyticShade(o, 315.0, 45.0)); });
  EXPECT_LE(multiplied.largest, 1.0);
  const Agreement alone = compare("alone", pipeline(file("cone.tif"), ", surface: paint, blend: alone", paint),
                                  [](Offset o) { return srgbLevel(analyticShade(o, 315.0, 45.0)); });
  EXPECT_LE(alone.largest, 1.0);
}

// A tint by elevation from blue at the base to red at the apex, blended in scene-linear light, times the
// shade: the red channel is (h / H) times the shade, h the cone's height there. By slope, from black at 0 to
// white at 90 degrees: the flank's slope over 90 degrees times the shade.
TEST_F(Relief, TintsByElevationOrSlope) {
  const std::string ramp = ", tint: elevation, tint_ramp: [0, 0, 0, 1, " + std::to_string(kConeHeight) + ", 1, 0, 0]";
  const Agreement agreement = compare("tint", pipeline(file("cone.tif"), ramp), [](Offset o) {
    return srgbLevel(coneHeight(o) / kConeHeight * analyticShade(o, 315.0, 45.0));
  });
  EXPECT_LE(agreement.largest, 1.0);
  const double slope = std::atan(kConeHeight / kConeRadius) / (0.5 * std::numbers::pi);
  const Agreement bySlope =
      compare("tint by slope", pipeline(file("cone.tif"), ", tint: slope, tint_ramp: [0, 0, 0, 0, 90, 1, 1, 1]"),
              [&](Offset o) { return srgbLevel(slope * analyticShade(o, 315.0, 45.0)); });
  EXPECT_LE(bySlope.largest, 1.0);
}

// A ramp that is not stops of four numbers with rising values is refused at its line.
TEST_F(Relief, RefusesAMalformedRamp) {
  const std::string text = pipeline(file("cone.tif"), ", tint: slope, tint_ramp: [10, 0, 0, 1, 5, 1, 0, 0]");
  try {
    engine_->load(directory_.write("ramp.yaml", text));
    ADD_FAILURE() << "a ramp of falling values was taken";
  } catch (const Error& error) {
    std::printf("%s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("do not rise"), std::string::npos) << error.what();
  }
}

// The height port takes height layers only.
TEST_F(Relief, RefusesAColourLayerAsHeight) {
  writeColourRaster(file("paint.tif"), 8, 8, {-kHalfExtent, -kHalfExtent, kHalfExtent, kHalfExtent}, [](int, int) {
    return Rgb8{1, 2, 3};
  });
  const std::string text =
      "strata: 1\nnodes:\n"
      "  paint: {type: source.gdal, path: " +
      file("paint.tif").string() +
      ", kind: color}\n"
      "  relief: {type: composite.relief, height: paint}\n"
      "  globe: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: globe, surface: [relief]}\n";
  try {
    engine_->load(directory_.write("refused.yaml", text));
    ADD_FAILURE() << "a colour layer was taken as heights";
  } catch (const Error& error) {
    std::printf("%s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("height"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace strata::test
