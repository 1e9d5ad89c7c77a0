// Heights displace the surface: the disc of a globe raised by a constant height has the radius of the
// larger sphere, to within rasterisation, whichever geometry generator draws it.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

// Half the number of lit pixels on the image's middle row.
double measuredDiscRadius(const Image& image) {
  int lit = 0;
  for (int x = 0; x < image.width; ++x) {
    auto p = image.at(x, image.height / 2);
    lit += (p[0] + p[1] + p[2]) > 0;
  }
  return lit / 2.0;
}

std::string raisedGlobePipeline(const std::filesystem::path& heights, double height, const std::string& geometry) {
  return "strata: 1\nbody: {name: Test, radius: 6371000}\ncamera: {lon: 0, lat: 0, altitude: 2.0e7, fov: 45}\nnodes:\n"
         "  heights: {type: source.gdal, path: " +
         heights.string() + ", kind: height, scale: " + std::to_string(height) +
         "}\n"
         "  globe: {type: " +
         geometry + ", height: heights, lowest: 0, highest: " + std::to_string(height) +
         "}\n"
         "  frame: {type: output.image, geometry: globe}\n";
}

class Silhouette : public ::testing::TestWithParam<std::tuple<double, std::string>> {};

TEST_P(Silhouette, DiscRadiusIsThatOfTheRaisedSphere) {
  TemporaryDirectory directory;
  writeFloatRaster(directory.path() / "one.tif", 8, 4, {-180, -90, 180, 90}, [](int, int) { return 1.0f; });
  const auto& [height, geometry] = GetParam();
  auto pipeline = directory.write("raised.yaml", raisedGlobePipeline(directory.path() / "one.tif", height, geometry));
  auto engine = makeEngine();
  Image image = renderFrame(*engine, pipeline, 640, 480);
  const View view = engine->view(640, 480);
  const double radius = engine->pipeline().body.radius;
  const double expected = discRadiusPixels(view, radius + height, glm::length(view.eye));
  // One pixel: each edge of the disc rasterises to within half a pixel; the mesh's chords (0.5 degree
  // edges) sink at most 60 m below the sphere, under a hundredth of a pixel here.
  EXPECT_NEAR(measuredDiscRadius(image), expected, 1.0) << "height " << height << " m";
}

// 0 m, then 300 km and 1000 km, which grow the disc by about 10 and 33 pixels.
INSTANTIATE_TEST_SUITE_P(Heights, Silhouette,
                         ::testing::Combine(::testing::Values(0.0, 3.0e5, 1.0e6),
                                            ::testing::Values("geometry.icosahedral", "geometry.pgm",
                                                              "geometry.healpix", "geometry.clipmap")),
                         [](const ::testing::TestParamInfo<std::tuple<double, std::string>>& test) {
                           const std::string& type = std::get<1>(test.param);
                           return type.substr(type.find('.') + 1) + "_" +
                                  std::to_string(int(std::get<0>(test.param) / 1000)) + "km";
                         });

}  // namespace
}  // namespace strata::test
