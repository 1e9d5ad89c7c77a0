// Every geometry generator covers every pixel of the planet and nothing else: from 100,000 km, from orbit,
// 1 km (also over the north pole) and 2 m above an Earth-sized body with procedural relief, looking down,
// tilted, with the horizon and the sky in view, and looking up. A crack between patches or nodes of
// different levels, or a mesh that stops short of the horizon or of the screen's edges, shows as a hole.
//
// geometry.pgm (shrinking, [Mahsman 2010, §3.3.1, Figs. 3.11, 3.12]; issue 5's "no holes at the horizon or the
// edges of the screen") is judged on the first frame after the camera jumps there (primary sphere: the
// minimum one, as sameSight refuses the least visible height of the view before) and the third (primary
// sphere: the least visible height of the frame before, which sits higher and is where shrinking would
// show). Before sameSight, the first frame after a jump from straight down to 50 degrees lost 111 pixels at
// a corner from 2 m, 187 from 1 km. geometry.healpix (issue 6: no cracks across level changes) and
// geometry.icosahedral are judged alike. Before healpix made its nodes' outline vertices on the CPU, it
// cracked between nodes: 1 or 2 pixels from 1 km, 60 to 306 from 2 m; and while it culled back faces one
// pixel stayed open 2 m up, tilted 88 degrees, behind a nearly edge-on triangle the rasteriser turned round.
// geometry.icosahedral cracked 2 m above relief of +-1 m (6 pixels looking down, 21 to 33 tilted 50 degrees)
// while source.procedural summed its noise at float planet-fixed points, 0.4 m apart on Earth; sampled
// from the reference (plugins/source-procedural/planet_lattice.hpp) it shows none.
//
// The generators take the relief's range from the layer (source.procedural's analytic bound): no `lowest`
// or `highest` is given. The reference is exact, in double: the relief lies within +-amplitude of the
// radius, so a pixel whose ray meets the lower sphere shows terrain, and one whose ray misses the
// upper sphere shows the sky. Pixels whose neighbours one pixel away (diagonally) disagree are left out:
// there the silhouette passes within the pixel, and a mesh of chords between grid points may lie either
// side of its centre.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <tuple>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr double kEarth = 6371000.0;  // m
constexpr int kWidth = 320, kHeight = 240;

// Procedural relief within +-amplitude of the radius, of a wavelength that the view resolves.
struct Scene {
  const char* name;             // the test's
  double altitude;              // m above the body's radius
  double amplitude;             // m
  double wavelength;            // m
  double lat;                   // deg: the point below the eye
  std::array<double, 4> tilts;  // deg from straight down
};

// The generator under test with its own settings: geometry.pgm's grid about a ray per pixel (the thesis's
// case grid = screen).
std::string terrainOf(const std::string& type) { return type == "geometry.pgm" ? type + ", grid: 256x256" : type; }

std::string pipelineFor(const Scene& scene, const std::string& type) {
  const std::string amplitude = std::to_string(scene.amplitude);
  return "strata: 1\nbody: {name: Earth, radius: " + std::to_string(kEarth) +
         "}\nnodes:\n"
         "  relief: {type: source.procedural, kind: height, amplitude: " +
         amplitude + ", wavelength: " + std::to_string(scene.wavelength) +
         "}\n"
         "  terrain: {type: " +
         terrainOf(type) +
         ", height: relief}\n"
         "  frame: {type: output.image, geometry: terrain, shading: none}\n";
}

// Whether the rays one pixel away diagonally from pixel (x, y) all meet (or all miss) the sphere.
int raysMeeting(const View& view, double radius, int x, int y) {
  int meeting = 0;
  for (const int dx : {-1, 1})
    for (const int dy : {-1, 1}) meeting += raycastSphere(view, radius, x + dx, y + dy).has_value();
  return meeting;
}

struct PixelCounts {
  int holes = 0;   // the ray meets the lowest sphere, and the pixel shows the sky
  int strays = 0;  // the ray misses the highest sphere, and the pixel shows terrain
  int ground = 0;  // pixels that must show terrain
  int sky = 0;     // pixels that must show the sky
};

PixelCounts measure(const Image& image, const View& view, const Scene& scene) {
  PixelCounts coverage;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool terrain = covered(image, x, y);
      if (raysMeeting(view, kEarth - scene.amplitude, x, y) == 4) {
        ++coverage.ground;
        coverage.holes += !terrain;
      } else if (raysMeeting(view, kEarth + scene.amplitude, x, y) == 0) {
        ++coverage.sky;
        coverage.strays += terrain;
      }
    }
  }
  return coverage;
}

class Coverage : public ::testing::TestWithParam<std::tuple<Scene, std::string>> {};

TEST_P(Coverage, EveryPixelOfThePlanetIsDrawnAndNoOther) {
  const auto& [scene, type] = GetParam();
  TemporaryDirectory directory;
  auto engine = makeEngine();
  engine->load(directory.write("coverage.yaml", pipelineFor(scene, type)));
  for (const double tilt : scene.tilts) {
    for (const int frames : {1, 3}) {
      const Camera camera{
          .lon = 12.0, .lat = scene.lat, .altitude = scene.altitude, .heading = 30.0, .tilt = tilt, .fov = 50.0};
      const Image image = renderFrames(*engine, camera, kWidth, kHeight, frames);
      const PixelCounts coverage = measure(image, makeView(engine->pipeline().body, camera, kWidth, kHeight), scene);
      std::printf("%s %s, tilt %3.0f, frame %d: %d holes, %d strays, %d pixels of ground, %d of sky\n", type.c_str(),
                  scene.name, tilt, frames, coverage.holes, coverage.strays, coverage.ground, coverage.sky);
      EXPECT_EQ(coverage.holes, 0) << "tilt " << tilt << ", frame " << frames;
      EXPECT_EQ(coverage.strays, 0) << "tilt " << tilt << ", frame " << frames;
      EXPECT_GT(coverage.ground + coverage.sky, kWidth * kHeight / 2);  // most pixels are judged
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Altitudes, Coverage,
    // From orbit the disc (14 degrees in radius) moves off-centre and, at 30 degrees,
    // across the bottom edge; from 100,000 km (a disc of 3.4 degrees) it leaves the
    // view. Near the ground the horizon and the sky come into view at 80 and 88
    // degrees, and at 180 the view looks at the sky alone. Over the north pole the
    // frame's reference latitude is 90 degrees.
    ::testing::Combine(::testing::Values(Scene{"FromOrbit", 2.0e7, 12000.0, 3.0e6, 47.0, {0.0, 12.0, 20.0, 30.0}},
                                         Scene{"FromFarAway", 1.0e8, 12000.0, 3.0e6, 47.0, {0.0, 20.0, 25.0, 40.0}},
                                         Scene{"FromOneKilometre", 1000.0, 300.0, 2.0e4, 47.0, {0.0, 50.0, 80.0, 88.0}},
                                         Scene{"OverThePole", 1000.0, 300.0, 2.0e4, 90.0, {0.0, 50.0, 80.0, 88.0}},
                                         Scene{"FromTwoMetres", 2.0, 1.0, 200.0, 47.0, {0.0, 50.0, 88.0, 180.0}}),
                       ::testing::Values("geometry.icosahedral", "geometry.pgm", "geometry.healpix",
                                         "geometry.clipmap")),
    [](const ::testing::TestParamInfo<std::tuple<Scene, std::string>>& test) {
      const std::string& type = std::get<1>(test.param);
      return std::string(std::get<0>(test.param).name) + "_" + type.substr(type.find('.') + 1);
    });

}  // namespace
}  // namespace strata::test
