// Surface layers land where they belong: every sampled pixel of a rendered checkerboard globe shows the
// colour of the cell that the analytic ray-sphere intersection (in double) finds under it, whichever
// geometry generator draws the globe. Near the poles the view sees beyond them, where a triangle interpolating the
// longitude across the meridian opposite the eye's would show a band of wrong cells (geometry.clipmap's seams due
// north and due south, [Clasen & Hege 2006, §4.4]).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <tuple>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

struct CameraCase {
  const char* name;
  double lon, lat, heading, tilt;
};

std::string checkerboardPipeline(const std::filesystem::path& raster, const CameraCase& c,
                                 const std::string& geometry) {
  return "strata: 1\n"
         "body: {name: Earth, radius: 6371000}\n"
         "camera: {lon: " +
         std::to_string(c.lon) + ", lat: " + std::to_string(c.lat) +
         ", altitude: 1.2e7, heading: " + std::to_string(c.heading) + ", tilt: " + std::to_string(c.tilt) +
         ", fov: 45}\n"
         "nodes:\n"
         "  cells: {type: source.gdal, path: " +
         raster.string() +
         ", kind: color}\n"
         "  globe: {type: " +
         geometry +
         "}\n"
         "  frame: {type: output.image, geometry: globe, surface: [cells], shading: none}\n";
}

// Degrees from `value` to the nearest multiple of 45: cell edges are blurred by filtering and by the
// mesh's chords (under 0.1 degree at this subdivision), so pixels within 2 degrees are not judged.
double distanceToCellEdge(double value) { return std::abs(value - 45.0 * std::round(value / 45.0)); }

class SurfaceColour : public ::testing::TestWithParam<std::tuple<CameraCase, std::string>> {};

TEST_P(SurfaceColour, EveryJudgedPixelShowsTheCellUnderIt) {
  TemporaryDirectory directory;
  writeCheckerboard(directory.path() / "cells.tif");
  const auto& [camera, geometry] = GetParam();
  auto pipeline = directory.write("globe.yaml", checkerboardPipeline(directory.path() / "cells.tif", camera, geometry));
  auto engine = makeEngine();
  const int width = 320, height = 240;
  Image image = renderFrame(*engine, pipeline, width, height);
  const View view = engine->view(width, height);
  const double radius = engine->pipeline().body.radius;

  int judged = 0, wrong = 0;
  for (int y = 1; y < height; y += 3)
    for (int x = 1; x < width; x += 3) {
      auto hit = raycastSphere(view, radius, x, y);
      auto pixel = image.at(x, y);
      if (!hit) {
        // Space is black, except at the limb where the mesh's chords and rasterisation differ by a pixel.
        if (!raycastSphere(view, radius * 1.01, x, y)) {
          EXPECT_EQ(pixel[0] + pixel[1] + pixel[2], 0) << x << "," << y;
        }
        continue;
      }
      // Grazing views (0.3 is about 73 degrees off-normal) are left out, and so are latitudes beyond 80
      // degrees: equirectangular texels stretch as 1/cos(latitude), past the 8x anisotropic filter there,
      // and blur across cell edges (the polar blur of [Kooima 2008, §4.1.1] that polar data will fix).
      if (hit->incidence < 0.3 || std::abs(hit->lat) > 80.0) continue;
      if (distanceToCellEdge(hit->lon) < 2.0 || distanceToCellEdge(hit->lat) < 2.0) continue;
      const int column = int(std::floor((hit->lon + 180.0) / 45.0)) % 8,
                row = int(std::floor((90.0 - hit->lat) / 45.0));
      const Rgb8 expected = cellColour(column, row);
      ++judged;
      // 2 levels: sRGB decode to half floats and re-encode to 8 bits round by under one level each way.
      bool matches = true;
      for (int c = 0; c < 3; ++c) matches &= std::abs(pixel[c] - int(expected[c])) <= 2;
      if (!matches && ++wrong <= 5)
        ADD_FAILURE() << "pixel " << x << "," << y << " at lon " << hit->lon << " lat " << hit->lat << " is ("
                      << pixel[0] << "," << pixel[1] << "," << pixel[2] << "), cell " << column << "," << row << " is ("
                      << int(expected[0]) << "," << int(expected[1]) << "," << int(expected[2]) << ")";
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(judged, 600) << "too few pixels were judged for the test to mean anything";
}

INSTANTIATE_TEST_SUITE_P(Cameras, SurfaceColour,
                         ::testing::Combine(::testing::Values(CameraCase{"PrimeMeridian", 0, 0, 0, 0},
                                                              CameraCase{"Antimeridian", 180, 10, 0, 0},
                                                              CameraCase{"NearTheNorthPole", 30, 70, 0, 0},
                                                              CameraCase{"NearTheSouthPole", -150, -70, 0, 0},
                                                              CameraCase{"TiltedAndTurned", -100, -30, 45, 25}),
                                            // geometry.clipmap also with 64 steps around (not 512): its columns
                                            // beyond the poles stand some 12 pixels wide, so that a seam shows.
                                            ::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap",
                                                              "geometry.clipmap, steps: 64")),
                         [](const ::testing::TestParamInfo<std::tuple<CameraCase, std::string>>& test) {
                           std::string type = std::get<1>(test.param).substr(std::get<1>(test.param).find('.') + 1);
                           std::erase_if(type, [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); });
                           return std::string(std::get<0>(test.param).name) + "_" + type;
                         });

// A regional raster `width` by 40 degrees centred on `centre` (its x range as written, e.g. 150 to 210 across
// the antimeridian), seen from above longitude `cameraLon`, far from the raster's centre or over it: the frame's
// reference lies there, so the raster's texels are addressed from offsets that cross the seam both ways, and
// across the map's own seam, half a turn from its centre, where the raster is wider than half the body.
struct PatchCase {
  const char* name;
  double centre, width, cameraLon;
};

// Longitude `lon` less `centre`, within half a turn (degrees).
double fromCentre(double lon, double centre) { return std::remainder(lon - centre, 360.0); }

class PatchExtent : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchExtent, OutsideALayersExtentTheEmptyColourShows) {
  const PatchCase& c = GetParam();
  TemporaryDirectory directory;
  writeFloatRaster(directory.path() / "patch.tif", int(c.width), 40,
                   {c.centre - 0.5 * c.width, -20, c.centre + 0.5 * c.width, 20}, [](int, int) { return 200.0f; });
  auto pipeline =
      directory.write("patch.yaml",
                      "strata: 1\ncamera: {lon: " + std::to_string(c.cameraLon) +
                          ", lat: 0, altitude: 1.2e7}\nnodes:\n"
                          "  patch: {type: source.gdal, path: " +
                          (directory.path() / "patch.tif").string() +
                          ", kind: luminance, scale: 0.00392156862745098}\n"  // 200/255 in linear light
                          "  globe: {type: geometry.icosahedral}\n"
                          "  frame: {type: output.image, geometry: globe, surface: [patch], shading: none}\n");
  auto engine = makeEngine();
  Image image = renderFrame(*engine, pipeline, 320, 240);
  const View view = engine->view(320, 240);
  // sRGB encodings of linear 200/255 (229) and of the empty colour, linear 0.18 (118).
  int inside = 0, outside = 0;
  for (int y = 2; y < 240; y += 4)
    for (int x = 2; x < 320; x += 4) {
      auto hit = raycastSphere(view, engine->pipeline().body.radius, x, y);
      if (!hit || hit->incidence < 0.3) continue;
      const double east = std::abs(fromCentre(hit->lon, c.centre));
      const bool wellInside = east < 0.5 * c.width - 2 && std::abs(hit->lat) < 18;
      const bool wellOutside = east > 0.5 * c.width + 2 || std::abs(hit->lat) > 22;
      if (!wellInside && !wellOutside) continue;
      const int expected = wellInside ? 229 : 118;
      EXPECT_NEAR(image.at(x, y)[0], expected, 2) << x << "," << y << " lon " << hit->lon << " lat " << hit->lat;
      ++(wellInside ? inside : outside);
    }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

INSTANTIATE_TEST_SUITE_P(Places, PatchExtent,
                         ::testing::Values(PatchCase{"AtTheOrigin", 0, 60, 0},
                                           PatchCase{"AcrossTheAntimeridian", 180, 60, 180},
                                           PatchCase{"AcrossTheAntimeridianSeenFromTheWest", 180, 60, 130},
                                           PatchCase{"AcrossTheAntimeridianSeenFromTheEast", 180, 60, -130},
                                           PatchCase{"EastOfTheAntimeridianSeenFromTheWest", 200, 60, 150},
                                           PatchCase{"AllButAGapSeenOverTheGap", 180, 300, 0}),
                         [](const ::testing::TestParamInfo<PatchCase>& test) { return test.param.name; });

}  // namespace
}  // namespace strata::test
