#include "observation.hpp"

#include <proj.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include <glm/glm.hpp>

namespace strata::testdata {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
const std::string kLongLat = "+proj=longlat +R=3396190";

bool everywhere(double, double) { return true; }

Observation global(const std::string& name, int width, int height) {
  const double pixelWidth = 360.0 / width, pixelHeight = 180.0 / height;
  return {.name = name,
          .crs = kLongLat,
          .width = width,
          .height = height,
          .west = -180.0,
          .north = 90.0,
          .pixelWidth = pixelWidth,
          .pixelHeight = pixelHeight,
          .footprint = std::max(pixelWidth, pixelHeight) * kDegree * kMarsRadius,
          .covers = everywhere};
}

// How far from the pole, in map metres, `crs` puts latitude `latDeg`: asked of PROJ, like every position
// in these data, so that nothing here shares code with the projections Strata implements.
double polarRadius(const std::string& crs, double latDeg) {
  std::unique_ptr<PJ, decltype(&proj_destroy)> projection(proj_create(nullptr, crs.c_str()), &proj_destroy);
  if (!projection) throw std::runtime_error("PROJ cannot make '" + crs + "'");
  const PJ_COORD mapped = proj_trans(projection.get(), PJ_FWD, proj_coord(0.0, latDeg * kDegree, 0.0, 0.0));
  return std::hypot(mapped.xy.x, mapped.xy.y);
}

// A polar stereographic cap (`crs`) down to latitude `edgeDeg` (its sign picks the pole), in a square raster
// of 1024 x 1024 that just holds the circle of that latitude. The footprint is the pixel size, which is
// true at the CRS's lat_ts and within 17% of it over the cap.
Observation polarCap(const std::string& name, const std::string& crs, double edgeDeg) {
  const double half = polarRadius(crs, edgeDeg), pixel = 2.0 * half / 1024;
  auto covers = [edge = edgeDeg * kDegree](double, double lat) { return edge > 0 ? lat >= edge : lat <= edge; };
  return {.name = name,
          .crs = crs,
          .width = 1024,
          .height = 1024,
          .west = -half,
          .north = half,
          .pixelWidth = pixel,
          .pixelHeight = pixel,
          .footprint = pixel,
          .covers = covers};
}

// The HEALPix plane (Calabretta and Roukema 2007) x in [-pi R, pi R], y in [-pi R / 2, pi R / 2]; its empty
// corners are where PROJ's inverse fails.
Observation healpix() {
  const double pixel = 2.0 * kPi * kMarsRadius / 2048;
  return {.name = "healpix",
          .crs = "+proj=healpix +R=3396190",
          .width = 2048,
          .height = 1024,
          .west = -kPi * kMarsRadius,
          .north = kPi / 2.0 * kMarsRadius,
          .pixelWidth = pixel,
          .pixelHeight = pixel,
          .footprint = pixel,
          .covers = everywhere};
}

// A strip at 4x the global resolution along the ground track of an orbit inclined 60 degrees with its
// ascending node at longitude 10: the track enters the box at its south-west corner and leaves at the
// north-east one. Only a band 3 degrees wide about the track's great circle has data (the overlay of
// [Kooima 2008, §4.2]).
Observation strip() {
  const double inclination = 60.0 * kDegree, node = 10.0 * kDegree;
  // The normal of the orbit's plane: the node's direction crossed with the direction of motion there.
  const glm::dvec3 pole(std::sin(node) * std::sin(inclination), -std::cos(node) * std::sin(inclination),
                        std::cos(inclination));
  auto covers = [pole](double lon, double lat) {
    const glm::dvec3 n(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    return std::abs(std::asin(glm::dot(pole, n))) <= 1.5 * kDegree;
  };
  const double pixel = 360.0 / 8192;  // 4x global's 2048 across
  return {.name = "strip",
          .crs = kLongLat,
          .width = 910,
          .height = 1365,
          .west = -10.0,
          .north = 30.0,
          .pixelWidth = pixel,
          .pixelHeight = pixel,
          .footprint = pixel * kDegree * kMarsRadius,
          .covers = covers};
}

}  // namespace

Observation galeStrip() {
  constexpr double kTexel = 0.25, lon = 137.4, lat = -4.6;  // m; deg
  constexpr int kWidth = 1024, kHeight = 4096;
  const double pixelHeight = kTexel / (kMarsRadius * kDegree), pixelWidth = pixelHeight / std::cos(lat * kDegree);
  return {.name = "gale",
          .crs = kLongLat,
          .width = kWidth,
          .height = kHeight,
          .west = lon - pixelWidth * kWidth / 2,
          .north = lat + pixelHeight * kHeight / 2,
          .pixelWidth = pixelWidth,
          .pixelHeight = pixelHeight,
          .footprint = kTexel,
          .covers = everywhere};
}

procedural::PlanetParameters finePlanetParameters() { return {.octaves = 24, .contourInterval = 1.0}; }

std::vector<Observation> standardObservations() {
  // The south cap is true to scale 19 degrees from its pole, as the Antarctic's EPSG:3031 is.
  return {global("global", 2048, 1024), polarCap("north", "+proj=stere +lat_0=90 +lat_ts=90 +R=3396190", 45.0),
          polarCap("south", "+proj=stere +lat_0=-90 +lat_ts=-71 +R=3396190", -45.0), healpix(), strip()};
}

Observation largeGlobalObservation(int width, int height) {
  return global("global-" + std::to_string(width) + "x" + std::to_string(height), width, height);
}

}  // namespace strata::testdata
