// Choosing the projection a raster is tiled into (docs/architecture.md, "Projections": any CRS PROJ knows is
// re-tiled into one of the built-in projections).
#include "tile_target.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include <strata/crs.hpp>

#include "projection/projection_terms.hpp"

namespace strata::tiling {
namespace {

// The built-in projections by name, on the raster's ellipsoid. The polar ones are true to scale at the
// pole, where a cap's data is densest. kHealpixPyramid is no projection but a layout, which tileRaster writes.
std::optional<std::string> namedTarget(const std::string& name, const OGRSpatialReference& crs) {
  const std::string figure = figureTerms(crs);
  if (name == "equirectangular") return "+proj=longlat" + figure;
  if (name == "polar-north") return "+proj=stere +lat_0=90 +lat_ts=90" + figure;
  if (name == "polar-south") return "+proj=stere +lat_0=-90 +lat_ts=-90" + figure;
  return std::nullopt;
}

bool isRegistered(const PluginRegistry& plugins, const OGRSpatialReference& crs) {
  try {
    projectionOfCrs(plugins, crs, {});
    return true;
  } catch (const Error&) {
    return false;
  }
}

struct Coverage {
  double south = 90.0, north = -90.0;
  bool northPole = false, southPole = false;
};

// The latitudes a raster covers, from a grid of points over it, and whether a pole lies on it.
Coverage coverageOf(const OGRSpatialReference& crs, const double t[6], int width, int height) {
  Coverage coverage;
  const Transformation toGeographic = geographicTransformation(crs);
  if (!toGeographic) return coverage;
  constexpr int kSamples = 33;  // per side; enough to find the extremes of any smooth projection's edges
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      double x = t[0] + t[1] * width * i / (kSamples - 1), y = t[3] + t[5] * height * j / (kSamples - 1);
      if (!toGeographic->Transform(1, &x, &y)) continue;
      coverage.south = std::min(coverage.south, y);
      coverage.north = std::max(coverage.north, y);
    }
  const Transformation toSource(toGeographic->GetInverse(), OGRCoordinateTransformation::DestroyCT);
  for (const double poleLatitude : {90.0, -90.0}) {
    double x = 0.0, y = poleLatitude;
    if (!toSource || !toSource->Transform(1, &x, &y)) continue;
    const double column = (x - t[0]) / t[1], row = (y - t[3]) / t[5];
    const bool inside = column >= 0.0 && column <= width && row >= 0.0 && row <= height;
    (poleLatitude > 0.0 ? coverage.northPole : coverage.southPole) = inside;
  }
  return coverage;
}

}  // namespace

Transformation geographicTransformation(const OGRSpatialReference& crs) {
  OGRSpatialReference geographic;
  geographic.CopyGeogCSFrom(&crs);
  geographic.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference source(crs);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return Transformation(OGRCreateCoordinateTransformation(&source, &geographic),
                        OGRCoordinateTransformation::DestroyCT);
}

std::string figureTerms(const OGRSpatialReference& crs) {
  return ellipsoidTerms(Ellipsoid{crs.GetSemiMajor(), crs.GetInvFlattening()});
}

std::string tileTarget(const PluginRegistry& plugins, const OGRSpatialReference& crs, const double geotransform[6],
                       int width, int height, const std::string& target, const SourceLocation& where) {
  if (!target.empty()) {
    if (auto named = namedTarget(target, crs)) return *named;
    if (target.find_first_of("+:[") == std::string::npos)
      throw Error(where, "'" + target + "' is neither a projection name nor a CRS",
                  "name one of equirectangular, polar-north, polar-south, " + std::string(kHealpixPyramid) +
                      " (a HEALPix pyramid), or give a PROJ string or EPSG:code");
    projectionOfCrs(plugins, target, where);  // a CRS given by hand must be one the cache can sample
    return target;
  }
  if (isRegistered(plugins, crs)) return {};
  // Beyond 60 degrees equirectangular texels are stretched more than 2:1 ([Kooima 2008, §4.1]).
  constexpr double kPolarLatitude = 60.0;
  const Coverage coverage = coverageOf(crs, geotransform, width, height);
  if (coverage.northPole || coverage.south >= kPolarLatitude) return *namedTarget("polar-north", crs);
  if (coverage.southPole || coverage.north <= -kPolarLatitude) return *namedTarget("polar-south", crs);
  return *namedTarget("equirectangular", crs);
}

}  // namespace strata::tiling
