#include "georeferencing.hpp"

#include <ogr_spatialref.h>

#include <cmath>
#include <cstdint>

#include <strata/crs.hpp>

namespace strata::gdal {
namespace {

std::string describe(GDALDataset& dataset) { return dataset.GetDescription(); }

bool isGeographic(const Projection& projection) {
  return ProjParameters::parse(projection.projString()).name() == "longlat";
}

std::unique_ptr<Projection> projectionOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                         const GeoreferenceOptions& options) {
  if (!options.crs.empty()) return projectionOfCrs(plugins, options.crs, options.crsWhere);
  if (const OGRSpatialReference* crs = dataset.GetSpatialRef()) return projectionOfCrs(plugins, *crs, options.fileWhere);
  return geographicProjection(plugins);
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

}  // namespace

RasterGeoreference georeferenceOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                  const GeoreferenceOptions& options) {
  std::unique_ptr<Projection> projection = projectionOf(dataset, plugins, options);
  const std::array<double, 6> geotransform = geotransformOf(dataset, *projection, options);
  return makeGeoreference(std::move(projection), geotransform, dataset.GetRasterXSize());
}

}  // namespace strata::gdal
