#include "georeferencing.hpp"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

#include <glm/vec2.hpp>

#include <strata/crs.hpp>
#include <strata/plugin/spherical_cap.hpp>

namespace strata::gdal {
namespace {

std::string describe(GDALDataset& dataset) { return dataset.GetDescription(); }

bool isGeographic(const Projection& projection) {
  return ProjParameters::parse(projection.projString()).name() == "longlat";
}

std::unique_ptr<Projection> projectionOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                         const GeoreferenceOptions& options) {
  if (!options.crs.empty()) return projectionOfCrs(plugins, options.crs, options.crsWhere);
  if (const OGRSpatialReference* crs = dataset.GetSpatialRef()) {
    try {
      return projectionOfCrs(plugins, *crs, options.fileWhere);
    } catch (const Error& error) {
      throw Error(options.fileWhere, "'" + describe(dataset) + "': " + error.problem(), error.fix());
    }
  }
  return geographicProjection(plugins);
}

// A raster without a CRS is read as longitude/latitude; a geotransform reaching beyond degrees says it is
// something else (metres of a projection), which would be drawn as garbage.
void refuseNonDegrees(GDALDataset& dataset, const std::array<double, 6>& t, const SourceLocation& where) {
  const double x0 = t[0], x1 = t[0] + t[1] * dataset.GetRasterXSize();
  const double y0 = t[3], y1 = t[3] + t[5] * dataset.GetRasterYSize();
  const double slack = 1e-6;  // degrees: rounding in geotransforms written as text
  if (std::min(x0, x1) >= -180.0 - slack && std::max(x0, x1) <= 360.0 + slack && std::min(y0, y1) >= -90.0 - slack &&
      std::max(y0, y1) <= 90.0 + slack)
    return;
  std::array<char, 160> span{};
  std::snprintf(span.data(), span.size(), "x %g to %g, y %g to %g", std::min(x0, x1), std::max(x0, x1),
                std::min(y0, y1), std::max(y0, y1));
  throw Error(where,
              "'" + describe(dataset) + "' has no CRS, and its geotransform spans " + span.data() +
                  ": not degrees of longitude and latitude",
              "assign its CRS: gdal_edit.py -a_srs CRS " + describe(dataset) + ", or give the source's `projection`");
}

GeographicExtent checkedExtent(const std::vector<double>& v, const SourceLocation& where) {
  const GeographicExtent extent{v[0], v[1], v[2], v[3]};
  if (!(extent.west < extent.east && extent.east - extent.west <= 360.0))
    throw Error(where, "extent west must be less than east, at most 360 degrees apart",
                "write [west, south, east, north]; across the antimeridian let east exceed 180");
  if (!(extent.south < extent.north && extent.south >= -90.0 && extent.north <= 90.0))
    throw Error(where, "extent south must be less than north, both within [-90, 90]",
                "write [west, south, east, north] in degrees");
  return extent;
}

std::array<double, 6> geotransformOf(GDALDataset& dataset, const Projection& projection,
                                     const GeoreferenceOptions& options) {
  const bool geographic = isGeographic(projection);
  if (!options.extent.empty()) {
    if (!geographic)
      throw Error(options.extentWhere, "`extent` is in degrees and places longitude/latitude rasters only",
                  "drop `extent` and georeference the file in its CRS: gdal_translate -a_ullr ulx uly lrx lry");
    const GeographicExtent extent = checkedExtent(options.extent, options.extentWhere);
    return geographicGeotransform(extent, dataset.GetRasterXSize(), dataset.GetRasterYSize());
  }
  std::array<double, 6> t{};
  if (dataset.GetGeoTransform(t.data()) == CE_None) {
    if (t[2] != 0.0 || t[4] != 0.0)
      throw Error(options.fileWhere, "'" + describe(dataset) + "' is a rotated grid, which is not supported",
                  "warp it to a north-up grid: gdalwarp in.tif out.tif (or strata tile)");
    return t;
  }
  if (geographic && dataset.GetRasterXSize() == 2 * std::int64_t{dataset.GetRasterYSize()})
    return geographicGeotransform({}, dataset.GetRasterXSize(), dataset.GetRasterYSize());
  throw Error(options.fileWhere,
              "'" + describe(dataset) + "' has no geotransform" +
                  (geographic ? " and is not 2:1, so its extent is unknown" : ", so its map area is unknown"),
              geographic ? "give `extent: [west, south, east, north]` in degrees"
                         : "georeference it: gdal_translate -a_ullr ulx uly lrx lry in.tif out.tif");
}

// A texel finer than this (rad of the body) is below what doubles of planet-sized values hold apart: a few
// micrometres on Earth, far below the centimetres Strata is built for.
constexpr double kFinestTexelAngle = 1e-12;

std::string geotransformText(const std::array<double, 6>& t) {
  std::array<char, 200> text{};
  std::snprintf(text.data(), text.size(), "%g, %g, %g, %g, %g, %g", t[0], t[1], t[2], t[3], t[4], t[5]);
  return text.data();
}

// The angle (rad) between two places on the body (longitude, latitude in rad).
double angleBetween(glm::dvec2 a, glm::dvec2 b) { return strata::angleBetween(directionOf(a), directionOf(b)); }

// A geotransform that places the raster nowhere on the body (NaN, infinite, texels of no size, or so far out
// that its texels fall together) would draw an empty planet: refused, naming the file.
void refuseNowhere(GDALDataset& dataset, const Projection& projection, const std::array<double, 6>& t,
                   const SourceLocation& where) {
  const auto mapOf = [&t](double column, double row) {
    return glm::dvec2(t[0] + column * t[1] + row * t[2], t[3] + column * t[4] + row * t[5]);
  };
  const double column = 0.5 * dataset.GetRasterXSize(), row = 0.5 * dataset.GetRasterYSize();
  const std::optional<glm::dvec2> centre = projection.inverse(mapOf(column, row));
  const std::optional<glm::dvec2> east = projection.inverse(mapOf(column + 1.0, row));
  const std::optional<glm::dvec2> south = projection.inverse(mapOf(column, row + 1.0));
  const bool finite = std::all_of(t.begin(), t.end(), [](double v) { return std::isfinite(v); });
  std::string problem;
  if (!finite || t[1] == 0.0 || t[5] == 0.0)
    problem = "is not finite or gives its texels no size";
  else if (!centre || !east || !south)
    problem = "places its centre outside its projection's domain";
  else if (std::min(angleBetween(*centre, *east), angleBetween(*centre, *south)) < kFinestTexelAngle)
    problem = "makes its texels finer than 1e-12 rad of the body, where doubles no longer hold them apart";
  if (problem.empty()) return;
  throw Error(
      where, "'" + describe(dataset) + "' has the geotransform " + geotransformText(t) + ", which " + problem,
      "correct it: gdal_edit.py -a_ullr ulx uly lrx lry " + describe(dataset) + " (gdalinfo shows what it says now)");
}

}  // namespace

RasterGeoreference georeferenceOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                  const GeoreferenceOptions& options) {
  std::unique_ptr<Projection> projection = projectionOf(dataset, plugins, options);
  const std::array<double, 6> geotransform = geotransformOf(dataset, *projection, options);
  if (options.crs.empty() && !dataset.GetSpatialRef()) refuseNonDegrees(dataset, geotransform, options.fileWhere);
  refuseNowhere(dataset, *projection, geotransform, options.fileWhere);
  return makeGeoreference(std::move(projection), geotransform, dataset.GetRasterXSize());
}

}  // namespace strata::gdal
