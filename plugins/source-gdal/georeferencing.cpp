#include "georeferencing.hpp"

#include <ogr_spatialref.h>

#include <array>
#include <cmath>

namespace strata::gdal {
namespace {

std::string describe(GDALDataset& dataset) { return dataset.GetDescription(); }

GeographicExtent fromGeotransform(GDALDataset& dataset, const std::array<double, 6>& t, const SourceLocation& where) {
  if (t[2] != 0.0 || t[4] != 0.0)
    throw Error(where, "'" + describe(dataset) + "' is a rotated grid, which is not supported",
                "warp it to a north-up grid: gdalwarp -t_srs EPSG:4326 in.tif out.tif");
  const double width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  GeographicExtent extent{t[0], t[3] + t[5] * height, t[0] + t[1] * width, t[3]};
  if (t[5] > 0) std::swap(extent.south, extent.north);
  // Grids registered at cell centres (EGM96's) reach half a cell past the poles; that is kept, so that
  // each cell centre samples at its own latitude.
  return extent;
}

}  // namespace

GeographicExtent extentOf(GDALDataset& dataset, const SourceLocation& where) {
  std::array<double, 6> transform{};
  const bool georeferenced = dataset.GetGeoTransform(transform.data()) == CE_None;
  const OGRSpatialReference* crs = dataset.GetSpatialRef();
  if (georeferenced && crs && !crs->IsGeographic())
    throw Error(where,
                "'" + describe(dataset) + "' is in the projected CRS '" + std::string(crs->GetName()) +
                    "'; source.gdal reads longitude/latitude rasters until the projections issue lands",
                "reproject it: gdalwarp -t_srs '+proj=longlat +R=<radius>' in.tif out.tif, or give `extent`");
  if (georeferenced) return fromGeotransform(dataset, transform, where);
  if (dataset.GetRasterXSize() == 2 * dataset.GetRasterYSize()) return GeographicExtent{};
  throw Error(where,
              "'" + describe(dataset) + "' has no georeferencing and is not 2:1, so its extent is unknown",
              "give `extent: [west, south, east, north]` in degrees");
}

GeographicExtent extentFromParameter(const std::vector<double>& v, const SourceLocation& where) {
  GeographicExtent extent{v[0], v[1], v[2], v[3]};
  if (!(extent.west < extent.east && extent.east - extent.west <= 360.0))
    throw Error(where, "extent west must be less than east, at most 360 degrees apart",
                "write [west, south, east, north]; across the antimeridian let east exceed 180");
  if (!(extent.south < extent.north && extent.south >= -90.0 && extent.north <= 90.0))
    throw Error(where, "extent south must be less than north, both within [-90, 90]",
                "write [west, south, east, north] in degrees");
  return extent;
}

}  // namespace strata::gdal
