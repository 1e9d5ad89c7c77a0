#pragma once
#include <memory>
#include <string>

#include "leaf_patch.hpp"

namespace strata::bdam {

// A height raster as `strata build-bdam` reads it: any raster GDAL opens, in any projection PROJ knows (a
// longitude/latitude grid, a polar stereographic cap, ...), its first band read whole, in metres above the body's
// sphere. A direction's height is bilinear between texel centres, as a layer samples it; a global longitude/latitude
// grid wraps east and west, nodata texels are left out of the weighting, and a place the raster does not cover has
// height 0 (the body's sphere). Longitude and latitude are taken on the sphere (planetocentric), as Strata's layers
// take them.
class RasterHeights {
 public:
  // Throws std::runtime_error naming the file and what is wrong with it.
  explicit RasterHeights(const std::string& path);
  ~RasterHeights();
  RasterHeights(const RasterHeights&) = delete;
  RasterHeights& operator=(const RasterHeights&) = delete;

  // The semi-major axis of the raster's CRS, m; 0 when it has no CRS.
  double bodyRadius() const;
  // A texel's width on the body, m (at the equator for a longitude/latitude grid), on a body of `radius`.
  double texelSize(double radius) const;
  // Heights at planet-fixed unit directions, for one thread (each sampler has its own coordinate transformation).
  HeightAt sampler() const;

 private:
  struct Grid;
  std::shared_ptr<const Grid> grid_;
};

}  // namespace strata::bdam
