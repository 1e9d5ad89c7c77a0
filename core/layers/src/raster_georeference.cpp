// Placing rasters: a projection plus a geotransform, with periodic projections centred on the raster.
#include <strata/crs.hpp>
#include <strata/plugin/plugin_registry.hpp>
#include <strata/plugin/raster_georeference.hpp>

namespace strata {

RasterGeoreference makeGeoreference(std::unique_ptr<Projection> projection, const std::array<double, 6>& geotransform,
                                    int width) {
  if (projection->periodX()) {  // periodic projections are defined at (0, 0), on the equator
    const glm::dvec2 centre{geotransform[0] + geotransform[1] * width / 2.0, projection->forward({0.0, 0.0})->y};
    if (auto lonlat = projection->inverse(centre)) projection->setLongitudeCentre(lonlat->x);
  }
  return {std::shared_ptr<const Projection>(std::move(projection)), geotransform};
}

std::array<double, 6> geographicGeotransform(const GeographicExtent& extent, int width, int height) {
  return {extent.west, (extent.east - extent.west) / width,   0.0, extent.north,
          0.0,         (extent.south - extent.north) / height};
}

RasterGeoreference geographicGeoreference(const PluginRegistry& plugins, const GeographicExtent& extent, int width,
                                          int height) {
  return makeGeoreference(geographicProjection(plugins), geographicGeotransform(extent, width, height), width);
}

}  // namespace strata
