// The plugin's shaders compute the planet the C++ model does: every judged pixel of a rendered globe shows
// the model's colour at the point the analytic ray-sphere intersection (in double) finds under it, with the
// octaves that pixel's footprint allows.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <ostream>
#include <string>

#include <glm/gtc/constants.hpp>

#include "planet_model.hpp"
#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "srgb_encoding.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

struct CameraCase {
  const char* name;
  double lon, lat, altitude, heading, tilt;
};

void PrintTo(const CameraCase& camera, std::ostream* out) { *out << camera.name; }

// The geometry at a quarter of its default pixel error: the footprint the shader takes (how far longitude and
// latitude move to the next pixel) is the derivative of the mesh's interpolated coordinates, constant across
// a triangle. Over the north pole from 4,000 km the default's triangles span footprints some 10% apart, and
// the octaves that allows moved 21 pixels' colours by 3 levels; this test judges the plugin, not the mesh.
std::string planetPipeline(const CameraCase& c) {
  return "strata: 1\n"
         "body: {name: Mars, radius: 3396190}\n"
         "camera: {lon: " +
         std::to_string(c.lon) + ", lat: " + std::to_string(c.lat) + ", altitude: " + std::to_string(c.altitude) +
         ", heading: " + std::to_string(c.heading) + ", tilt: " + std::to_string(c.tilt) +
         ", fov: 45}\n"
         "nodes:\n"
         "  planet: {type: source.procedural, kind: color}\n"
         "  globe: {type: geometry.icosahedral, pixel_error: 0.25}\n"
         "  frame: {type: output.image, geometry: globe, surface: [planet], shading: none}\n";
}

glm::dvec3 normalOf(const SurfaceHit& hit) { return unitNormal(glm::radians(hit.lon), glm::radians(hit.lat)); }

// The change of (lon, lat) in radians from `here` to the pixel one step away, or back from the one on the
// other side at the body's edge, with the 2 pi jump removed: what plugins/output-image/composite.frag computes.
std::optional<glm::dvec2> footprintStep(const View& view, double radius, int x, int y, int dx, int dy,
                                        const SurfaceHit& here) {
  std::optional<SurfaceHit> other = raycastSphere(view, radius, x + dx, y + dy);
  if (!other) other = raycastSphere(view, radius, x - dx, y - dy);
  if (!other) return std::nullopt;
  glm::dvec2 d = glm::radians(glm::dvec2(other->lon - here.lon, other->lat - here.lat));
  d.x -= glm::two_pi<double>() * std::round(d.x / glm::two_pi<double>());
  return d;
}

// Metres of ground to the next pixel, the longer of the two steps, as plugins/source-procedural/planet.glsl has it.
double footprintMetres(const glm::dvec2& dx, const glm::dvec2& dy, double latDeg, double radius) {
  const double cosLat = std::cos(glm::radians(latDeg));
  return radius * std::max(glm::length(glm::dvec2(dx.x * cosLat, dx.y)), glm::length(glm::dvec2(dy.x * cosLat, dy.y)));
}

class ProceduralRender : public ::testing::TestWithParam<CameraCase> {};

TEST_P(ProceduralRender, EveryJudgedPixelShowsTheModelsColour) {
  TemporaryDirectory directory;
  auto pipeline = directory.write("planet.yaml", planetPipeline(GetParam()));
  auto engine = makeEngine();
  const int width = 320, height = 240;
  Image image = renderFrame(*engine, pipeline, width, height);
  const View view = engine->view(width, height);
  const double radius = engine->pipeline().body.radius;
  const procedural::PlanetModel planet({}, radius);

  int judged = 0, judgedOnLines = 0, wrong = 0, worst = 0;
  for (int y = 1; y < height - 1; y += 2)
    for (int x = 1; x < width - 1; x += 2) {
      const std::optional<SurfaceHit> hit = raycastSphere(view, radius, x, y);
      // Grazing views are left out: there the mesh's chords (0.5 degree edges) move the sample sideways.
      if (!hit || hit->incidence < 0.3) continue;
      // Image rows run down, the frame's up: the step to the row above is composite.frag's +y.
      const auto dx = footprintStep(view, radius, x, y, 1, 0, *hit);
      const auto dy = footprintStep(view, radius, x, y, 0, -1, *hit);
      const auto right = raycastSphere(view, radius, x + 1, y), above = raycastSphere(view, radius, x, y - 1);
      if (!dx || !dy || !right || !above) continue;
      const double footprint = footprintMetres(*dx, *dy, hit->lat, radius);
      const double h = planet.height(normalOf(*hit), footprint);
      // The rendered sample lies within a small part of a pixel of the reference point (chords sink 30 m at
      // most, under 100 m sideways at the incidences judged, against pixels of kilometres), so its height
      // is within half the change to the next pixel; 10 m more covers float rounding. Pixels nearer a
      // colour step than that may rightly show either colour and are not judged.
      const double change = std::max(std::abs(planet.height(normalOf(*right), footprint) - h),
                                     std::abs(planet.height(normalOf(*above), footprint) - h));
      if (planet.distanceToColourStep(h) < 0.5 * change + 10.0) continue;
      const std::array<std::uint8_t, 3> expected = procedural::encodeSrgb8(planet.colour(h));
      const std::array<int, 4> pixel = image.at(x, y);
      ++judged;
      judgedOnLines += planet.onContour(h);
      int error = 0;
      for (std::size_t c = 0; c < 3; ++c) error = std::max(error, std::abs(pixel[c] - int(expected[c])));
      worst = std::max(worst, error);
      // 2 levels: the frame rounds float colours to 8 bits as the reference rounds exact ones, which differ
      // by at most 1 level while the float colour is within half a level of the exact one; the float heights
      // (within a few metres of the double ones, and the ramp's steepest part, rock to snow, changes 0.13
      // levels per metre) get one level more. The worst seen on llvmpipe is 1.
      if (error > 2 && ++wrong <= 5)
        ADD_FAILURE() << "pixel " << x << "," << y << " at lon " << hit->lon << " lat " << hit->lat << " (height " << h
                      << " m, footprint " << footprint << " m) is (" << pixel[0] << "," << pixel[1] << "," << pixel[2]
                      << "), the model says (" << int(expected[0]) << "," << int(expected[1]) << "," << int(expected[2])
                      << ")";
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(judged, 1500) << "too few pixels were judged for the test to mean anything";
  EXPECT_GT(judgedOnLines, 10) << "too few pixels on contour lines were judged";
  RecordProperty("judged", judged);
  RecordProperty("judged_on_contour_lines", judgedOnLines);
  RecordProperty("worst_error_levels", worst);
}

// The whole disc with the equator and the prime meridian, a closer oblique view with more octaves, and a
// view over the north pole, where longitude wraps at every pixel around it.
INSTANTIATE_TEST_SUITE_P(Cameras, ProceduralRender,
                         ::testing::Values(CameraCase{"WholeDisc", 0, 0, 1.0e7, 0, 0},
                                           CameraCase{"CloserAndTilted", 100, -35, 1.5e6, 30, 20},
                                           CameraCase{"OverTheNorthPole", 0, 80, 4.0e6, 0, 0}),
                         [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace strata::test
