#include "projection_cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include "projection/builtin_projections.hpp"

namespace strata::test {
namespace {

constexpr double kPi = std::numbers::pi;

std::string figureTerms(const Ellipsoid& ellipsoid) {
  char text[96];
  if (ellipsoid.inverseFlattening == 0.0)
    std::snprintf(text, sizeof text, " +R=%.17g", ellipsoid.semiMajorAxis);
  else
    std::snprintf(text, sizeof text, " +a=%.17g +rf=%.17g", ellipsoid.semiMajorAxis, ellipsoid.inverseFlattening);
  return text;
}

// The full x range of a projection that does not wrap around the body.
double boundedRangeX(const ProjectionCase& projectionCase, const Projection& projection, const ProjReference& proj) {
  const glm::dvec2 centre = glm::radians(projectionCase.centre);
  const double a = projectionCase.ellipsoid.semiMajorAxis;
  if (projection.type() == "polar-stereographic")
    return 2.0 * glm::length(*proj.forward({centre.x + 0.5 * kPi, 0.0}) - *proj.forward(centre));
  if (projection.type() == "orthographic") return 2.0 * a;
  const double height = ProjParameters::parse(projectionCase.terms).real("h", 0.0);
  return 2.0 * a * std::sqrt(height / (height + 2.0 * a));  // the horizon's diameter on the vertical plane
}

}  // namespace

std::vector<ProjectionCase> projectionCases() {
  return {
      {"geographic_mars", "+proj=longlat", kMars, {0, 0}},
      {"geographic_wgs84", "+proj=longlat", kWgs84, {0, 0}},
      {"geographic_moon_lon0", "+proj=longlat +lon_0=10", kMoon, {10, 0}},
      {"eqc_mars", "+proj=eqc +lat_ts=0 +lat_0=0 +lon_0=0 +x_0=0 +y_0=0", kMars, {0, 0}},
      {"eqc_moon_lat_ts30", "+proj=eqc +lat_ts=30 +lon_0=180 +x_0=1000 +y_0=-2000", kMoon, {180, 0}},
      {"eqc_wgs84_lat_ts_south", "+proj=eqc +lat_ts=-45 +lat_0=10 +lon_0=-60", kWgs84, {-60, 0}},
      {"stere_mars_north_pole_scale", "+proj=stere +lat_0=90 +lat_ts=90", kMars, {0, 90}},
      {"stere_wgs84_south_71", "+proj=stere +lat_0=-90 +lat_ts=-71 +lon_0=0", kWgs84, {0, -90}},
      {"stere_wgs84_north_70", "+proj=stere +lat_0=90 +lat_ts=70 +lon_0=-45", kWgs84, {-45, 90}},
      {"stere_moon_south_60", "+proj=stere +lat_0=-90 +lat_ts=-60 +lon_0=30 +x_0=100000 +y_0=200000", kMoon, {30, -90}},
      {"stere_wgs84_north_k0", "+proj=stere +lat_0=90 +k=0.994 +x_0=2000000 +y_0=2000000", kWgs84, {0, 90}},
      {"stere_mars_south_k0", "+proj=stere +lat_0=-90 +k_0=0.97 +lon_0=100", kMars, {100, -90}},
      {"stere_mars_north_equator_true", "+proj=stere +lat_0=90 +lat_ts=0", kMars, {0, 90}},
      {"ups_wgs84_south", "+proj=ups +south", kWgs84, {0, -90}},
      {"ups_wgs84_north", "+proj=ups", kWgs84, {0, 90}},
      {"healpix_mars", "+proj=healpix", kMars, {0, 0}},
      {"healpix_moon_lon0", "+proj=healpix +lon_0=30 +x_0=1000 +y_0=-500", kMoon, {30, 0}},
      {"healpix_wgs84", "+proj=healpix", kWgs84, {0, 0}},
      {"healpix_wgs84_lon0", "+proj=healpix +lon_0=-120", kWgs84, {-120, 0}},
      {"ortho_moon_equatorial", "+proj=ortho +lat_0=0 +lon_0=0", kMoon, {0, 0}},
      {"ortho_mars_north", "+proj=ortho +lat_0=90", kMars, {0, 90}},
      {"ortho_mars_oblique", "+proj=ortho +lat_0=-25 +lon_0=137", kMars, {137, -25}},
      {"ortho_wgs84_equatorial", "+proj=ortho +lat_0=0 +lon_0=20", kWgs84, {20, 0}},
      {"ortho_wgs84_south", "+proj=ortho +lat_0=-90 +lon_0=45", kWgs84, {45, -90}},
      {"ortho_wgs84_oblique", "+proj=ortho +lat_0=40 +lon_0=-100 +x_0=100 +y_0=200", kWgs84, {-100, 40}},
      {"nsper_wgs84_geostationary", "+proj=nsper +h=35786000 +lat_0=0 +lon_0=0", kWgs84, {0, 0}},
      {"nsper_mars_oblique", "+proj=nsper +h=500000 +lat_0=-30 +lon_0=77", kMars, {77, -30}},
      {"nsper_mars_north", "+proj=nsper +h=1000000 +lat_0=90", kMars, {0, 90}},
      {"nsper_moon_low", "+proj=nsper +h=3000 +lat_0=10 +lon_0=20", kMoon, {20, 10}},
      {"tpers_wgs84", "+proj=tpers +h=1000000 +lat_0=40 +lon_0=-100 +tilt=30 +azi=45", kWgs84, {-100, 40}},
      {"tpers_mars_steep",
       "+proj=tpers +h=200000 +lat_0=-60 +lon_0=120 +tilt=60 +azi=-120 +x_0=500 +y_0=-700",
       kMars,
       {120, -60}},
      {"tpers_moon_polar", "+proj=tpers +h=5000000 +lat_0=90 +tilt=-20 +azi=10", kMoon, {0, 90}},
  };
}

void PrintTo(const ProjectionCase& projectionCase, std::ostream* out) {
  *out << projectionCase.name << " (" << referenceDefinition(projectionCase) << ")";
}

std::string referenceDefinition(const ProjectionCase& projectionCase) {
  return projectionCase.terms + figureTerms(projectionCase.ellipsoid);
}

std::unique_ptr<Projection> makeProjection(const std::string& terms, const Ellipsoid& ellipsoid) {
  const ProjParameters parameters = ProjParameters::parse(terms);
  for (const ProjectionDeclaration& declaration : builtinProjections())
    for (const std::string& projName : declaration.projNames)
      if (projName == parameters.name()) return declaration.create(parameters, ellipsoid);
  throw std::runtime_error("no built-in projection for '" + terms + "'");
}

std::unique_ptr<Projection> makeProjection(const ProjectionCase& projectionCase) {
  return makeProjection(projectionCase.terms, projectionCase.ellipsoid);
}

bool MapWindow::contains(glm::dvec2 xy) const {
  return xy.x >= min.x && xy.x <= max.x && xy.y >= min.y && xy.y <= max.y;
}

MapWindow mapWindow(const ProjectionCase& projectionCase, const Projection& projection, const ProjReference& proj) {
  const glm::dvec2 centre = glm::radians(projectionCase.centre);
  const glm::dvec2 middle = *proj.forward(centre);
  if (const auto period = projection.periodX()) {
    const double south = proj.forward({centre.x, -0.5 * kPi})->y;
    const double north = proj.forward({centre.x, 0.5 * kPi})->y;
    return {{middle.x - 0.5 * *period, south}, {middle.x + 0.5 * *period, north}, *period};
  }
  const double range = boundedRangeX(projectionCase, projection, proj);
  return {middle - 0.75 * range, middle + 0.75 * range, range};
}

std::vector<glm::dvec2> mapSamples(const MapWindow& window, int count) {
  std::vector<glm::dvec2> samples;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i)
      samples.push_back(window.min + (glm::dvec2(i, j) + 0.5) / double(count) * (window.max - window.min));
  return samples;
}

std::vector<glm::dvec2> lonlatSamples(const ProjReference& proj, const MapWindow& window, int lonCount, int latCount,
                                      int mapCount) {
  std::vector<glm::dvec2> samples;
  const double capBoundary = std::asin(2.0 / 3.0);
  const double specialLatitudes[] = {0.5 * kPi - 1e-8, 0.5 * kPi - 1e-4, capBoundary - 1e-9, capBoundary,
                                     capBoundary + 1e-9};
  for (int i = 0; i < lonCount; ++i) {
    const double lon = -kPi + (i + 0.5) * 2.0 * kPi / lonCount;
    for (int j = 0; j < latCount; ++j) samples.emplace_back(lon, -0.5 * kPi + j * kPi / (latCount - 1));
    if (i % 8 != 0) continue;
    for (double lat : specialLatitudes) {
      samples.emplace_back(lon, lat);
      samples.emplace_back(lon, -lat);
    }
  }
  for (glm::dvec2 xy : mapSamples(window, mapCount))
    if (const auto lonlat = proj.inverse(xy)) samples.push_back(*lonlat);
  return samples;
}

bool nearRim(const Projection& projection, glm::dvec2 lonlat, double delta) {
  const bool here = projection.forward(lonlat).has_value();
  const glm::dvec3 point(std::cos(lonlat.y) * std::cos(lonlat.x), std::cos(lonlat.y) * std::sin(lonlat.x),
                         std::sin(lonlat.y));
  // Steps of the unit vector along the axes reach across the poles, where steps in longitude do not.
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      glm::dvec3 step(0.0);
      step[axis] = sign * delta;
      const glm::dvec3 near = glm::normalize(point + step);
      const glm::dvec2 nearLonlat(std::atan2(near.y, near.x), std::asin(std::clamp(near.z, -1.0, 1.0)));
      if (projection.forward(nearLonlat).has_value() != here) return true;
    }
  return false;
}

bool nearSeam(const Projection& projection, glm::dvec2 lonlat, double delta, double jump) {
  const auto here = projection.forward(lonlat);
  if (!here) return false;
  for (glm::dvec2 step :
       {glm::dvec2(delta, 0.0), glm::dvec2(-delta, 0.0), glm::dvec2(0.0, delta), glm::dvec2(0.0, -delta)}) {
    const auto there = projection.forward({lonlat.x + step.x, std::clamp(lonlat.y + step.y, -0.5 * kPi, 0.5 * kPi)});
    if (there && glm::length(*there - *here) > jump) return true;
  }
  return false;
}

double mapDistance(const Projection& projection, glm::dvec2 a, glm::dvec2 b) {
  glm::dvec2 difference = a - b;
  if (const auto period = projection.periodX()) difference.x -= *period * std::round(difference.x / *period);
  return glm::length(difference);
}

}  // namespace strata::test
