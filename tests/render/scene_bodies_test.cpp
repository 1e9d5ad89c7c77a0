// A scene of several bodies (`bodies:`): the Earth and the Moon in one frame, each hiding the other where it
// lies nearer along the ray, judged against rays cast at both spheres in double; the camera tied to either
// body; and the lunar ground from 2 m up drawn as the Moon alone draws it, with the Earth 384,000 km away in
// its sky.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <strata/date.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 200;
constexpr double kEarthRadius = 6371000.0, kMoonRadius = 1737400.0;

enum class Seen { Space, Earth, Moon };

// Which body the ray through the centre of pixel (x, y) of `view` meets first, the view's body centred at
// `viewCentre` in the scene and the spheres at their centres; computed in double.
Seen castRay(const View& view, const glm::dvec3& viewCentre, const glm::dvec3& moonCentre, int x, int y) {
  const glm::dvec2 half = view.halfFrameTangents();
  const glm::dvec3 inEye((2.0 * (x + 0.5) / view.width - 1.0) * half.x, (1.0 - 2.0 * (y + 0.5) / view.height) * half.y,
                         -1.0);
  const glm::dvec3 direction = glm::normalize(glm::transpose(view.planetToEye) * inEye);
  const glm::dvec3 origin = viewCentre + view.eye;
  const auto hit = [&](const glm::dvec3& centre, double radius) -> std::optional<double> {
    const glm::dvec3 toCentre = centre - origin;
    const double along = glm::dot(toCentre, direction);
    const double miss = glm::dot(toCentre, toCentre) - along * along;
    if (miss > radius * radius || along <= 0.0) return std::nullopt;
    return along - std::sqrt(radius * radius - miss);
  };
  const std::optional<double> earth = hit(glm::dvec3(0.0), kEarthRadius), moon = hit(moonCentre, kMoonRadius);
  if (!earth && !moon) return Seen::Space;
  if (!moon || (earth && *earth < *moon)) return Seen::Earth;
  return Seen::Moon;
}

// The Earth is blue, the Moon red, both unlit (view: Raw), so a pixel says which body it shows.
Seen seenIn(const Image& image, int x, int y) {
  const auto pixel = image.at(x, y);
  if (pixel[2] > 128 && pixel[0] < 64) return Seen::Earth;
  if (pixel[0] > 128 && pixel[2] < 64) return Seen::Moon;
  return Seen::Space;
}

class SceneBodies : public ::testing::Test {
 protected:
  void SetUp() override {
    writeColourRaster(blue_, 16, 8, {-180.0, -90.0, 180.0, 90.0}, [](int, int) { return Rgb8{0, 0, 255}; });
    writeColourRaster(red_, 16, 8, {-180.0, -90.0, 180.0, 90.0}, [](int, int) { return Rgb8{255, 0, 0}; });
    directory_.write("earth.yaml", onePlain("Earth", blue_));
    directory_.write("moon.yaml", onePlain("Moon", red_));
  }

  // A body of one colour, unlit, without antialiasing: each pixel shows the surface at its centre.
  static std::string onePlain(const std::string& body, const std::filesystem::path& colour) {
    return "strata: 1\nbody: {name: " + body + "}\nnodes:\n  colour: {type: source.gdal, path: '" + colour.string() +
           "', kind: color}\n  surface: {type: geometry.icosahedral}\n"
           "  frame: {type: output.image, geometry: surface, surface: [colour], shading: none, antialiasing: none, "
           "view: Raw}\n";
  }

  // The Earth at the origin and the Moon at `moon` (m), seen by `camera`.
  std::filesystem::path scene(const glm::dvec3& moon, const std::string& camera) {
    return directory_.write("scene.yaml", "strata: 1\ncamera: " + camera +
                                              "\nbodies:\n  earth: {pipeline: earth.yaml}\n"
                                              "  moon: {pipeline: moon.yaml, position: [" +
                                              std::to_string(moon.x) + ", " + std::to_string(moon.y) + ", " +
                                              std::to_string(moon.z) + "]}\n");
  }

  // Judges every pixel but those within two pixels of a place where the rays change body (the limb of a sphere
  // drawn as triangles lies up to a pixel inside the true one): `wrongAt(x, y, expected)` says what is wrong with
  // the frame there, or nothing. Returns how many pixels were judged for each body; fails on the wrong ones.
  static std::array<int, 3> judgePixels(const View& view, const glm::dvec3& viewCentre, const glm::dvec3& moon,
                                        const std::function<std::string(int, int, Seen)>& wrongAt) {
    std::array<int, 3> counts{};
    int wrong = 0;
    for (int y = 2; y < kSize - 2; ++y)
      for (int x = 2; x < kSize - 2; ++x) {
        const Seen expected = castRay(view, viewCentre, moon, x, y);
        bool edge = false;
        for (int dy = -2; dy <= 2 && !edge; ++dy)
          for (int dx = -2; dx <= 2 && !edge; ++dx) edge = castRay(view, viewCentre, moon, x + dx, y + dy) != expected;
        if (edge) continue;
        ++counts[int(expected)];
        if (const std::string problem = wrongAt(x, y, expected); !problem.empty() && ++wrong <= 5)
          ADD_FAILURE() << "pixel (" << x << ", " << y << "), where the rays meet body " << int(expected) << ": "
                        << problem;
      }
    EXPECT_EQ(wrong, 0);
    return counts;
  }

  // Renders the scene and judges every pixel against the double ray cast: it shows the body the rays meet first.
  std::array<int, 3> judge(const std::filesystem::path& file, const glm::dvec3& moon) {
    auto engine = makeEngine();
    const Image image = renderFrame(*engine, file, kSize, kSize);
    const glm::dvec3 viewCentre = engine->camera().body == "moon" ? moon : glm::dvec3(0.0);
    return judgePixels(engine->view(kSize, kSize), viewCentre, moon, [&](int x, int y, Seen expected) {
      return seenIn(image, x, y) == expected ? std::string() : "shows body " + std::to_string(int(seenIn(image, x, y)));
    });
  }

  TemporaryDirectory directory_;
  std::filesystem::path blue_ = directory_.path() / "blue.tif", red_ = directory_.path() / "red.tif";
};

// From 1,000,000 km over the Earth's longitude 0 the Moon, 384,000 km toward the eye and 4,000 km aside, covers
// part of the Earth's disc.
TEST_F(SceneBodies, TheMoonInFrontHidesTheEarth) {
  const glm::dvec3 moon(3.844e8, 4.0e6, 0.0);
  const auto counts = judge(scene(moon, "{lon: 0, lat: 0, altitude: 1.0e9, fov: 1.5}"), moon);
  EXPECT_GT(counts[int(Seen::Moon)], 300);
  EXPECT_GT(counts[int(Seen::Earth)], 1000);
}

// The Moon as far behind the Earth, 9,500 km aside: the Earth hides part of it.
TEST_F(SceneBodies, TheEarthInFrontHidesTheMoon) {
  const glm::dvec3 moon(-3.844e8, 9.5e6, 0.0);
  const auto counts = judge(scene(moon, "{lon: 0, lat: 0, altitude: 1.0e9, fov: 1.5}"), moon);
  EXPECT_GT(counts[int(Seen::Moon)], 50);
  EXPECT_GT(counts[int(Seen::Earth)], 1000);
}

// The camera tied to the Moon: 620,000 km above its longitude 0, looking back past it at the Earth behind.
TEST_F(SceneBodies, TheCameraTiedToTheMoonSeesItBeforeTheEarth) {
  const glm::dvec3 moon(3.844e8, 4.0e6, 0.0);
  const auto counts = judge(scene(moon, "{body: moon, lon: 0, lat: 0, altitude: 6.2e8, fov: 1.5}"), moon);
  EXPECT_GT(counts[int(Seen::Moon)], 300);
  EXPECT_GT(counts[int(Seen::Earth)], 1000);
}

// From 2 m above the Moon's longitude 95, looking east at the horizon, the Earth (384,000 km off, toward -x)
// stands 5 degrees up. The ground, a 5 cm checkerboard under the eye, is drawn as the Moon alone draws it (within
// a level), and the Earth's disc where the rays meet it: each body is drawn with its own near plane, 2 mm for
// the ground, 380 km for the Earth.
TEST_F(SceneBodies, TheLunarGroundFromTwoMetresUpKeepsItsDepthWithTheEarthInItsSky) {
  const glm::dvec3 moon(3.844e8, 0.0, 0.0);
  const std::string camera = "{lon: 95, lat: 0, altitude: 2, heading: 90, tilt: 90, fov: 20}";
  std::string groundWithBoard =
      onePlain("Moon", red_) + "  board: {type: source.checker, lon: 95, lat: 0, cell: 0.05}\n";
  groundWithBoard.replace(groundWithBoard.find("surface: [colour]"), 17, "surface: [colour, board]");
  directory_.write("moon.yaml", groundWithBoard);
  auto alone = makeEngine();
  const Image moonAlone =
      renderFrame(*alone, directory_.write("alone.yaml", groundWithBoard + "camera: " + camera + "\n"), kSize, kSize);
  auto engine = makeEngine();
  const Image image = renderFrame(*engine, scene(moon, "{body: moon, " + camera.substr(1)), kSize, kSize);
  const auto counts = judgePixels(engine->view(kSize, kSize), moon, moon, [&](int x, int y, Seen expected) {
    const auto pixel = image.at(x, y), reference = moonAlone.at(x, y);
    if (expected == Seen::Earth) return seenIn(image, x, y) == Seen::Earth ? std::string() : std::string("no Earth");
    for (int c = 0; c < 3; ++c)
      if (std::abs(pixel[c] - reference[c]) > 1)
        return "(" + std::to_string(pixel[0]) + ", " + std::to_string(pixel[1]) + ", " + std::to_string(pixel[2]) +
               "), where the Moon alone drew (" + std::to_string(reference[0]) + ", " + std::to_string(reference[1]) +
               ", " + std::to_string(reference[2]) + ")";
    return std::string();
  });
  EXPECT_GT(counts[int(Seen::Earth)], 100);
  EXPECT_GT(counts[int(Seen::Moon)], 10000);
}

// The Moon on its orbit, lit by the sun of the scene's date: its near side (seen from over its longitude 0) full
// at the total lunar eclipse of 2022 November 8 (the Earth's shadow is not drawn) and dark at the new Moon of the
// solar eclipse of 2024 April 8; the date moved between frames, as the viewer's slider moves it, moves both the
// Moon and the sun.
TEST_F(SceneBodies, TheMoonsPhaseFollowsTheDate) {
  directory_.write("lit.yaml", "strata: 1\nbody: {name: Moon}\nnodes:\n  colour: {type: source.gdal, path: '" +
                                   blue_.string() +
                                   "', kind: color}\n  surface: {type: geometry.icosahedral}\n"
                                   "  frame: {type: output.image, geometry: surface, surface: [colour], shading: sun, "
                                   "ambient: 0, antialiasing: none, view: Raw}\n");
  const auto file = directory_.write(
      "phases.yaml",
      "strata: 1\ndate: 2022-11-08T10:59Z\ncamera: {body: moon, lon: 0, lat: 0, altitude: 1.0e7, fov: 20}\n"
      "bodies:\n  earth: {pipeline: earth.yaml}\n  moon: {pipeline: lit.yaml, orbit: moon}\n");
  auto engine = makeEngine();
  const int centre = kSize / 2;
  EXPECT_GT(renderFrame(*engine, file, kSize, kSize).at(centre, centre)[2], 240);  // the sun overhead: full blue
  engine->date() = *parseIsoDate("2024-04-08T18:17Z");
  EXPECT_EQ(renderFrames(*engine, engine->camera(), kSize, kSize, 1).at(centre, centre)[2], 0);  // night
}

}  // namespace
}  // namespace strata::test
