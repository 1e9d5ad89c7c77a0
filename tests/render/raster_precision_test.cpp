// Issue 27: a GeoTIFF of 1 cm texels (a 16 cm checkerboard, 10 m across, longitude/latitude on an
// Earth-radius sphere) is crisp wherever it lies: at lon 0 lat 0, at Gale crater's place (lon 137.4,
// lat -4.6), across the antimeridian on both sides, and a tenth of a degree from the pole, seen from 2 m
// straight down and tilted 60 degrees, with each generator. Every pixel whose texel footprint lies in one
// cell, by a ray cast in double against the sphere, must show that cell's colour within 2 levels. Sampled
// through absolute float longitude and latitude (the path before issue 27), the board at lon 137.4 was one
// flat grey and at lon 10 drawn in blocks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <tuple>

#include <glm/gtc/constants.hpp>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "board_judging.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"
#include "test_rasters.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 256;
constexpr double kRadius = 6371000.0;  // m: the pipeline's body
constexpr double kTexel = 0.01;        // m
constexpr int kTexels = 1024;
// 16 texels a cell: mip levels 1 to 4 stay inside cells. 32 for a board warped into another projection,
// whose filtering blurs more of each cell's edge (judgeBoard).
constexpr int kCellTexels = 16, kWarpedCellTexels = 32;
constexpr unsigned char kLight = 231, kDark = 48;

// Where a board lies: its centre and where the camera is, in degrees.
struct Place {
  const char* name;
  double lon, lat;              // the board's centre
  double cameraLon, cameraLat;  // a little off it, so that no symmetry hides an offset
};

void PrintTo(const Place& place, std::ostream* out) { *out << place.name; }

// The board of 1 cm texels centred at `place`, of cells `cellTexels` a side.
BoardGrid boardAt(const Place& place, int cellTexels) {
  BoardGrid board;
  board.lonStep = glm::degrees(kTexel / (kRadius * std::cos(glm::radians(place.lat))));
  board.latStep = glm::degrees(kTexel / kRadius);
  board.west = place.lon - board.lonStep * kTexels / 2;
  board.north = place.lat + board.latStep * kTexels / 2;
  board.columns = board.rows = kTexels;
  board.cellTexels = cellTexels;
  return board;
}

std::array<double, 4> extentOf(const BoardGrid& board) {
  return {board.west, board.north - board.latStep * board.rows, board.west + board.lonStep * board.columns,
          board.north};
}

// Writes the board at `place`, warped into `projection` by strata tile unless it is empty, renders it with
// `geometry` tilted `tilt` degrees from 2 m above the ground and expects every judged pixel to show its
// cell's colour. The ground is the sphere, or with `plateau` (m) a height layer that raises the whole body
// by that much, so that the eye is 2 m from the ground and `plateau` + 2 m from the sphere.
void expectCrisp(const Place& place, const std::string& geometry, double tilt, const std::string& projection,
                 double plateau = 0.0) {
  TemporaryDirectory directory;
  const int side = projection.empty() ? kCellTexels : kWarpedCellTexels;
  const BoardGrid board = boardAt(place, side);
  writeColourRaster(directory.path() / "board.tif", kTexels, kTexels, extentOf(board), [side](int column, int row) {
    const unsigned char grey = (column / side + row / side) % 2 == 0 ? kLight : kDark;
    return Rgb8{grey, grey, grey};
  });
  std::string raster = "board.tif";
  if (!projection.empty()) {
    raster = "warped.tif";
    tileRaster(PluginRegistry{}, {directory.path() / "board.tif", directory.path() / raster, projection});
  }
  std::string ground;
  if (plateau != 0.0) {
    writeFloatRaster(directory.path() / "plateau.tif", 8, 4, {-180, -90, 180, 90},
                     [plateau](int, int) { return float(plateau); });
    ground = "  plateau: {type: source.gdal, kind: height, path: plateau.tif}\n";
  }
  const auto pipeline = directory.write(
      "board.yaml",
      "strata: 1\nbody: {name: sphere, radius: 6371000}\n"
      "camera: {lon: " +
          pipelineDegrees(place.cameraLon) + ", lat: " + pipelineDegrees(place.cameraLat) +
          ", altitude: " + std::to_string(plateau + 2.0) + ", heading: 30, tilt: " + std::to_string(tilt) +
          ", fov: 40}\nnodes:\n"
          "  board: {type: source.gdal, path: " +
          raster + "}\n" + ground + "  globe: {type: " + geometry + (plateau != 0.0 ? ", height: plateau" : "") +
          "}\n"
          "  frame: {type: output.image, geometry: globe, surface: [board], shading: none}\n");
  auto engine = makeEngine();
  const Image image = renderFrame(*engine, pipeline, kSize, kSize);
  const View view = engine->view(kSize, kSize);
  const Judgement judgement = judgeBoard(image, view, kRadius + plateau, board, !projection.empty(), kLight, kDark);
  EXPECT_GT(judgement.judged, kSize * kSize / 5);
  EXPECT_EQ(judgement.wrong, 0) << "of " << judgement.judged << " pixels";
}

class RasterPrecision : public ::testing::TestWithParam<std::tuple<Place, std::string, double>> {};

TEST_P(RasterPrecision, OneCentimetreTexelsAreCrispFromTwoMetres) {
  const auto& [place, geometry, tilt] = GetParam();
  expectCrisp(place, geometry, tilt, "");
}

// The camera 1.37 m east and 0.5 m north of the board's centre (in metres on the ground); across the
// antimeridian from either side.
const Place kPlaces[] = {
    {"origin", 0.0, 0.0, 1.23e-5, 4.5e-6},
    {"gale", 137.4, -4.6, 137.4 + 1.23e-5, -4.6 + 4.5e-6},
    {"antimeridian_east", 180.0, 10.0, -179.99998, 10.0 + 4.5e-6},
    {"antimeridian_west", -180.0, -10.0, 179.99998, -10.0 + 4.5e-6},
    {"near_north_pole", 33.0, 89.95, 33.0 + 0.0123, 89.95 + 4.5e-6},
};

std::string placeGeneratorAndTilt(const ::testing::TestParamInfo<std::tuple<Place, std::string, double>>& param) {
  const std::string& type = std::get<1>(param.param);
  return std::string(std::get<0>(param.param).name) + "_" + type.substr(type.find('.') + 1) + "_tilt" +
         std::to_string(int(std::get<2>(param.param)));
}

INSTANTIATE_TEST_SUITE_P(PlacesGeneratorsAndTilts, RasterPrecision,
                         ::testing::Combine(::testing::ValuesIn(kPlaces),
                                            ::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(0.0, 60.0)),
                         placeGeneratorAndTilt);

}  // namespace
}  // namespace strata::test

namespace strata::test {
namespace {

// The board warped to polar stereographic (strata tile --to polar-north): near the pole, where the
// projection is true, and at 10 degrees north, where it is far from linear over the reach.
class WarpedRasterPrecision : public ::testing::TestWithParam<std::tuple<Place, double>> {};

TEST_P(WarpedRasterPrecision, OneCentimetreTexelsInPolarStereographicAreCrispFromTwoMetres) {
  const auto& [place, tilt] = GetParam();
  expectCrisp(place, "geometry.icosahedral", tilt, "polar-north");
}

INSTANTIATE_TEST_SUITE_P(PlacesAndTilts, WarpedRasterPrecision,
                         ::testing::Combine(::testing::Values(kPlaces[4], kPlaces[2]), ::testing::Values(0.0, 60.0)),
                         [](const ::testing::TestParamInfo<std::tuple<Place, double>>& param) {
                           return std::string(std::get<0>(param.param).name) + "_tilt" +
                                  std::to_string(int(std::get<1>(param.param)));
                         });

}  // namespace
}  // namespace strata::test

namespace strata::test {
namespace {

// The board as a HEALPix pyramid (strata tile --to healpix): 1 cm texels need nside 2^30 (6 mm face texels
// on Earth), far beyond the twelve faces' 2^26, so the pyramid holds the window of one face the board
// covers: on an equatorial face at Gale's place, on face 6 across the antimeridian, and on a polar face a
// tenth of a degree from the pole, where the faces' texels are sheared most. Through float strip
// coordinates (face + x, 2^-24 apart) a texel address would be 64 texels astray.
class HealpixRasterPrecision : public ::testing::TestWithParam<std::tuple<Place, std::string, double>> {};

TEST_P(HealpixRasterPrecision, OneCentimetreTexelsInAHealpixPyramidAreCrispFromTwoMetres) {
  const auto& [place, geometry, tilt] = GetParam();
  expectCrisp(place, geometry, tilt, "healpix");
}

INSTANTIATE_TEST_SUITE_P(Places, HealpixRasterPrecision,
                         ::testing::Combine(::testing::Values(kPlaces[1], kPlaces[3], kPlaces[4]),
                                            ::testing::Values("geometry.icosahedral"), ::testing::Values(0.0, 60.0)),
                         placeGeneratorAndTilt);
INSTANTIATE_TEST_SUITE_P(Generators, HealpixRasterPrecision,
                         ::testing::Combine(::testing::Values(kPlaces[1]),
                                            ::testing::Values("geometry.pgm", "geometry.healpix", "geometry.clipmap"),
                                            ::testing::Values(60.0)),
                         placeGeneratorAndTilt);

}  // namespace
}  // namespace strata::test

namespace strata::test {
namespace {

// 2 m above a plateau 3 km high the board must be as crisp as 2 m above the sphere: the geometry's detail
// and the pages the cache loads follow the distance to the ground, not to the sphere, which lies 3 km
// below (from 3 km, 1 cm texels are far finer than a pixel, and the coarse level that would be drawn
// blurs the cells to grey). The generators know the ground from the height layer's range.
class PlateauRasterPrecision : public ::testing::TestWithParam<std::string> {};

TEST_P(PlateauRasterPrecision, OneCentimetreTexelsAreCrispTwoMetresAboveAPlateau) {
  expectCrisp(kPlaces[1], GetParam(), 0.0, "", 3000.0);
}

INSTANTIATE_TEST_SUITE_P(Generators, PlateauRasterPrecision,
                         ::testing::Values("geometry.icosahedral", "geometry.pgm", "geometry.healpix",
                                           "geometry.clipmap"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param.substr(param.param.find('.') + 1);
                         });

}  // namespace
}  // namespace strata::test
