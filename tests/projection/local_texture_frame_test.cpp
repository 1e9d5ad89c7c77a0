// Texture coordinates about the frame's reference (core/layers/src/local_texture_frame.cpp), in double
// through the built-in projections' own forward mappings: within the reach the polynomial agrees with the
// exact mapping to the tolerance asked (a hundredth of a texel of a 1 cm raster 10 m across), in the
// coordinates that reach farther on the ground.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <strata/crs.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "layers/local_texture_frame.hpp"

namespace strata {
namespace {

constexpr double kRadius = 6371000.0;       // m
constexpr double kRasterMetres = 10.0;      // a 1024-texel raster of 1 cm texels, about
constexpr double kTolerance = 0.01 / 1024;  // uv: a hundredth of one of its texels

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// uv of a raster kRasterMetres across, centred at `centre`, in the map of `crs` (metres, or degrees
// scaled to metres on the sphere for longitude/latitude).
TextureMapping rasterAt(const Projection& projection, glm::dvec2 centre, glm::dvec2 metresPerUnit) {
  const glm::dvec2 origin = *projection.forward(centre);
  return [&projection, origin, metresPerUnit](glm::dvec2 lonlat) -> std::optional<glm::dvec2> {
    const std::optional<glm::dvec2> xy = projection.forward(lonlat);
    if (!xy) return std::nullopt;
    return (*xy - origin) * metresPerUnit / kRasterMetres + 0.5;
  };
}

// The polynomial against the mapping at random offsets within the reach.
void expectAgreesWithin(const LocalTextureFrame& frame, const TextureMapping& mapping, glm::dvec2 reference) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    glm::dvec2 offset(unit(random), unit(random));
    if (glm::length(offset) > 1.0) continue;
    offset *= frame.reach;
    const glm::dvec2 lonlat =
        frame.coordinates == LocalCoordinates::LonLat ? reference + offset : lonlatOfTangentOffset(reference, offset);
    if (std::abs(lonlat.y) > 0.5 * std::numbers::pi) continue;
    const glm::dvec2 error = frame.at(offset) - *mapping(lonlat);
    EXPECT_LE(std::max(std::abs(error.x), std::abs(error.y)), kTolerance)
        << "at offset " << offset.x << ", " << offset.y;
  }
}

TEST(LocalTextureFrame, LongitudeLatitudeIsExactlyLinearAndReachesFarthest) {
  const PluginRegistry plugins;
  const auto projection = geographicProjection(plugins);
  const glm::dvec2 reference(radians(137.4), radians(-4.6));
  const double metresPerDegree = radians(1.0) * kRadius;
  const TextureMapping mapping = rasterAt(*projection, reference, glm::dvec2(metresPerDegree, metresPerDegree));
  const LocalTextureFrame frame = localTextureFrame(mapping, reference, glm::dvec2(kTolerance), false);
  EXPECT_EQ(frame.coordinates, LocalCoordinates::LonLat);
  EXPECT_GE(frame.reach, 0.01) << "rad: the map is linear in longitude and latitude";
  EXPECT_NEAR(frame.uv.x, 0.5, 1e-9);
  expectAgreesWithin(frame, mapping, reference);
}

// Near its pole polar stereographic curves in longitude offsets at the scale of the distance to the pole
// (5.6 km here): in the tangent plane it is smooth at the scale of the radius.
TEST(LocalTextureFrame, PolarStereographicNearThePoleTakesTheTangentPlane) {
  const PluginRegistry plugins;
  const auto projection = projectionOfCrs(plugins, "+proj=stere +lat_0=90 +lat_ts=90 +R=6371000", {"test"});
  const glm::dvec2 reference(radians(33.0), radians(89.95));
  const TextureMapping mapping = rasterAt(*projection, reference, glm::dvec2(1.0, 1.0));
  const LocalTextureFrame frame = localTextureFrame(mapping, reference, glm::dvec2(kTolerance), false);
  EXPECT_EQ(frame.coordinates, LocalCoordinates::Tangent);
  EXPECT_GE(frame.reach, 2e-4) << "rad on the ground: 1.3 km, far beyond what a view 2 m up resolves";
  expectAgreesWithin(frame, mapping, reference);
}

TEST(LocalTextureFrame, AMappingUndefinedAtTheReferenceHasNoReach) {
  const PluginRegistry plugins;
  const auto projection = projectionOfCrs(plugins, "+proj=ortho +lat_0=0 +lon_0=0 +R=6371000", {"test"});
  const TextureMapping mapping = [&](glm::dvec2 lonlat) -> std::optional<glm::dvec2> {
    return projection->forward(lonlat);
  };
  EXPECT_EQ(localTextureFrame(mapping, {radians(180.0), 0.0}, glm::dvec2(kTolerance), false).reach, 0.0)
      << "the far side";
}

// The tangent plane's offsets, east then north, land where the unit sphere puts them: a step e east leaves
// the parallel, which curves away from the plane, by e^2 tan(lat) / 2 of latitude.
TEST(LocalTextureFrame, TangentOffsetsLandEastAndNorthOfTheReference) {
  const glm::dvec2 reference(radians(-60.0), radians(45.0));
  const glm::dvec2 east = lonlatOfTangentOffset(reference, {1e-6, 0.0});
  EXPECT_NEAR((east.x - reference.x) * std::cos(reference.y), 1e-6, 1e-15);
  EXPECT_NEAR(east.y, reference.y - 0.5e-12 * std::tan(reference.y), 1e-15);
  const glm::dvec2 north = lonlatOfTangentOffset(reference, {0.0, 1e-6});
  EXPECT_NEAR(north.x, reference.x, 1e-15);
  EXPECT_NEAR(north.y - reference.y, 1e-6, 1e-15);
}

}  // namespace
}  // namespace strata
