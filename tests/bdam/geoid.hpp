#pragma once
// EGM96's geoid (proj-data, 15' texels) for geometry.bdam's tests: real heights that nobody here generated.
#include <gdal.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/glm.hpp>

namespace strata::bdam {

class Geoid {
 public:
  Geoid() {
    GDALAllRegister();
    dataset_ = GDALOpen("/usr/share/proj/egm96_15.gtx", GA_ReadOnly);
    if (!dataset_) throw std::runtime_error("cannot open /usr/share/proj/egm96_15.gtx (proj-data)");
    GDALGetGeoTransform(dataset_, transform_);
  }
  ~Geoid() { GDALClose(dataset_); }
  Geoid(const Geoid&) = delete;
  Geoid& operator=(const Geoid&) = delete;

  // m at a longitude and latitude, deg: bilinear between the texels' centres, as a layer samples it (the grid
  // wraps east and west).
  double at(double lon, double lat) const {
    const double x = (lon - transform_[0]) / transform_[1] - 0.5, y = (lat - transform_[3]) / transform_[5] - 0.5;
    const double fx = x - std::floor(x), fy = y - std::floor(y);
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    return (1 - fy) * ((1 - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
           fy * ((1 - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
  }
  // m at a planet-fixed unit direction.
  double at(const glm::dvec3& direction) const {
    const double degrees = 180.0 / std::numbers::pi;
    return at(std::atan2(direction.y, direction.x) * degrees, std::asin(std::clamp(direction.z, -1.0, 1.0)) * degrees);
  }

 private:
  double texel(int x, int y) const {
    const int width = GDALGetRasterXSize(dataset_), height = GDALGetRasterYSize(dataset_);
    float value = 0.0f;
    if (GDALRasterIO(GDALGetRasterBand(dataset_, 1), GF_Read, ((x % width) + width) % width,
                     std::clamp(y, 0, height - 1), 1, 1, &value, 1, 1, GDT_Float32, 0, 0) != CE_None)
      throw std::runtime_error("cannot read the geoid");
    return value;
  }

  GDALDatasetH dataset_ = nullptr;
  double transform_[6] = {};
};

}  // namespace strata::bdam
