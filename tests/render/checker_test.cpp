// Issues 4 and 5: a 1 cm checkerboard laid on the ground (source.checker) renders crisp and steady from 2 m
// above an Earth-sized body, drawn by each geometry generator. Every pixel whose 3x3 neighbourhood lies in one cell, by
// a ray cast in double against the sphere, must show that cell's colour; the eye then moves by millimetres and the
// board must stay where the rays say it is. A board drawn 2 mm out of place (1.4 pixels below the eye) fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kAnchorLon = 10.0, kAnchorLat = 45.0, kCell = 0.01;  // deg, deg, m
constexpr int kLight = 231, kDark = 48;                               // sRGB of the board's linear 0.8 and 0.03

struct Board {
  double radius;
  // The cell a point lies in, counted in double from the anchor; -1 for the sky.
  std::optional<glm::ivec2> cellAt(const View& view, int x, int y) const {
    const std::optional<SurfaceHit> hit = raycastSphere(view, radius, x, y);
    if (!hit) return std::nullopt;
    const double column = glm::radians(hit->lon - kAnchorLon) * radius * std::cos(glm::radians(kAnchorLat)) / kCell;
    const double row = glm::radians(hit->lat - kAnchorLat) * radius / kCell;
    return glm::ivec2(int(std::floor(column)), int(std::floor(row)));
  }
};

struct Judgement {
  int judged = 0;
  int wrong = 0;
};

// Judges the pixels well inside a cell: all eight neighbours in the same one, so that the box filter over
// the pixel's footprint sees one colour.
Judgement judge(const Image& image, const View& view, const Board& board) {
  Judgement result;
  for (int y = 1; y < kHeight - 1; ++y)
    for (int x = 1; x < kWidth - 1; ++x) {
      const std::optional<glm::ivec2> cell = board.cellAt(view, x, y);
      if (!cell) continue;
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1 && inside; ++dx) inside = board.cellAt(view, x + dx, y + dy) == cell;
      if (!inside) continue;
      ++result.judged;
      const int expected = (cell->x + cell->y) % 2 == 0 ? kLight : kDark;
      // 2 levels: the frame rounds to 8 bits after float arithmetic.
      if (std::abs(image.at(x, y)[1] - expected) > 2) ++result.wrong;
    }
  return result;
}

// Degrees to a billionth of a millimetre on the ground: the camera moves by millimetres.
std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12f", value);
  return text;
}

class CheckerBoard : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(CheckerBoard, StaysCrispAndStillFromTwoMetres) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const auto& [geometry, tilt] = GetParam();
  for (const double eastMillimetres : {0.0, 1.0, 3.0, 7.0}) {
    const double lon =
        kAnchorLon + glm::degrees(0.137 + eastMillimetres * 1e-3) / (6371000.0 * std::cos(glm::radians(kAnchorLat)));
    const auto pipeline = directory.write(
        "board.yaml", "strata: 1\ncamera: {lon: " + degrees(lon) + ", lat: " + degrees(kAnchorLat + 2e-6) +
                          ", altitude: 2, heading: 30, tilt: " + std::to_string(tilt) +
                          ", fov: 20}\nnodes:\n"
                          "  board: {type: source.checker, lon: 10, lat: 45, cell: 0.01}\n"
                          "  globe: {type: " +
                          geometry +
                          "}\n"
                          "  frame: {type: output.image, geometry: globe, surface: [board], shading: none}\n");
    const Image image = renderFrame(*engine, pipeline, kWidth, kHeight);
    const View view = engine->view(kWidth, kHeight);
    const Judgement result = judge(image, view, Board{engine->pipeline().body.radius});
    EXPECT_GT(result.judged, kWidth * kHeight / 5) << eastMillimetres << " mm east";
    EXPECT_EQ(result.wrong, 0) << "of " << result.judged << " pixels, " << eastMillimetres << " mm east";
  }
}

// With a 20 degree field of view a cell below the eye is 7 pixels across. Looking straight down, and
// tilted 30 degrees, where cells at the top of the frame shrink to 4 pixels.
INSTANTIATE_TEST_SUITE_P(GeneratorsAndTilts, CheckerBoard,
                         ::testing::Combine(::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(0.0, 30.0)),
                         [](const ::testing::TestParamInfo<std::tuple<std::string, double>>& param) {
                           const std::string& type = std::get<0>(param.param);
                           return type.substr(type.find('.') + 1) + "_tilt" +
                                  std::to_string(int(std::get<1>(param.param)));
                         });

}  // namespace
}  // namespace strata::test
