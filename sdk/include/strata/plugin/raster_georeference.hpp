#pragma once
#include <array>
#include <memory>
#include <strata/export.hpp>

#include <strata/plugin/projection.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// Where a raster's texels lie on the body: a projection, and GDAL's affine geotransform from the
// (column, row) of texel corners to map coordinates: x = t[0] + column t[1], y = t[3] + row t[5]. Grids
// are north-up (t[2] = t[4] = 0); t[5] is negative when row 0 is the north edge.
struct RasterGeoreference {
  std::shared_ptr<const Projection> projection;
  std::array<double, 6> geotransform{0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
};

// The georeference of a raster `width` texels wide: a periodic projection is centred on the raster, so
// that longitudes wrap into its x range (a map of [0, 360) degrees sees longitude -10 as 350).
RasterGeoreference makeGeoreference(std::unique_ptr<Projection> projection, const std::array<double, 6>& geotransform,
                                    int width);

// A longitude/latitude box in degrees. East may exceed 180 for boxes across the antimeridian.
struct GeographicExtent {
  double west = -180.0;
  double south = -90.0;
  double east = 180.0;
  double north = 90.0;
};

// The geotransform (in degrees) and the georeference of a longitude/latitude raster of `width` x `height`
// texels covering `extent`.
std::array<double, 6> geographicGeotransform(const GeographicExtent& extent, int width, int height);
RasterGeoreference geographicGeoreference(const PluginRegistry& plugins, const GeographicExtent& extent, int width,
                                          int height);

}  // namespace strata
STRATA_EXPORTS_END
