#include "raster_heights.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace strata::bdam {

struct RasterHeights::Grid {
  int width = 0, height = 0;
  std::vector<float> values;  // NaN where the raster has no data
  std::array<double, 6> geotransform{};
  bool wrapsEastWest = false;                // a longitude/latitude grid a whole turn wide
  std::unique_ptr<OGRSpatialReference> crs;  // null: longitude/latitude without a CRS
  double radius = 0.0;

  double texel(int column, int row) const {
    if (wrapsEastWest) column = ((column % width) + width) % width;
    if (column < 0 || column >= width || row < 0 || row >= height) return std::nan("");
    return values[std::size_t(row) * std::size_t(width) + std::size_t(column)];
  }

  // Bilinear between texel centres, nodata left out; 0 where nothing is covered.
  double at(double x, double y) const {
    const double column = (x - geotransform[0]) / geotransform[1] - 0.5,
                 row = (y - geotransform[3]) / geotransform[5] - 0.5;
    const double c0 = std::floor(column), r0 = std::floor(row), fx = column - c0, fy = row - r0;
    double sum = 0.0, weights = 0.0;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double value = texel(int(c0) + dx, int(r0) + dy), weight = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
        if (std::isfinite(value) && weight > 0.0) sum += weight * value, weights += weight;
      }
    return weights > 0.0 ? sum / weights : 0.0;
  }

  // A longitude within the grid's turn, for a grid in degrees of [0, 360) or [-180, 180).
  double wrappedLongitude(double lon) const {
    const double west = std::min(geotransform[0], geotransform[0] + width * geotransform[1]);
    while (lon < west) lon += 360.0;
    while (lon >= west + 360.0) lon -= 360.0;
    return lon;
  }
};

namespace {

std::runtime_error problem(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what);
}

std::unique_ptr<OGRCoordinateTransformation> fromLonLat(const OGRSpatialReference& crs) {
  if (!crs.IsProjected()) return nullptr;
  OGRSpatialReference geographic;
  geographic.CopyGeogCSFrom(&crs);
  geographic.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return std::unique_ptr<OGRCoordinateTransformation>(OGRCreateCoordinateTransformation(&geographic, &crs));
}

}  // namespace

RasterHeights::RasterHeights(const std::string& path) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset) throw problem(path, std::string("cannot be read as a raster: ") + CPLGetLastErrorMsg());
  auto grid = std::make_shared<Grid>();
  grid->width = dataset->GetRasterXSize();
  grid->height = dataset->GetRasterYSize();
  if (dataset->GetGeoTransform(grid->geotransform.data()) != CE_None || grid->geotransform[2] != 0.0 ||
      grid->geotransform[4] != 0.0)
    throw problem(path, "has no north-up geotransform: give it one (gdal_translate -a_ullr, or gdalwarp)");
  if (const OGRSpatialReference* crs = dataset->GetSpatialRef()) {
    grid->crs = std::make_unique<OGRSpatialReference>(*crs);
    grid->crs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    grid->radius = crs->GetSemiMajor();
  }
  grid->wrapsEastWest = (!grid->crs || !grid->crs->IsProjected()) &&
                        std::abs(std::abs(grid->width * grid->geotransform[1]) - 360.0) < 1e-6;
  GDALRasterBand& band = *dataset->GetRasterBand(1);
  grid->values.resize(std::size_t(grid->width) * std::size_t(grid->height));
  if (band.RasterIO(GF_Read, 0, 0, grid->width, grid->height, grid->values.data(), grid->width, grid->height,
                    GDT_Float32, 0, 0) != CE_None)
    throw problem(path, std::string("cannot be read: ") + CPLGetLastErrorMsg());
  int hasNodata = 0;
  const double nodata = band.GetNoDataValue(&hasNodata);
  if (hasNodata) std::replace(grid->values.begin(), grid->values.end(), float(nodata), std::nanf(""));
  if (grid->crs && grid->crs->IsProjected() && !fromLonLat(*grid->crs))
    throw problem(path, "its CRS cannot be reached from longitude and latitude by PROJ");
  grid_ = std::move(grid);
}

RasterHeights::~RasterHeights() = default;

double RasterHeights::bodyRadius() const { return grid_->radius; }
double RasterHeights::texelSize(double radius) const {
  const double width = std::abs(grid_->geotransform[1]);
  return grid_->crs && grid_->crs->IsProjected() ? width * grid_->crs->GetLinearUnits()
                                                 : width * std::numbers::pi / 180.0 * radius;
}

HeightAt RasterHeights::sampler() const {
  std::shared_ptr<OGRCoordinateTransformation> transformation;
  if (grid_->crs) transformation = fromLonLat(*grid_->crs);
  return [grid = grid_, transformation](const glm::dvec3& direction) {
    const double degrees = 180.0 / std::numbers::pi;
    double x = std::atan2(direction.y, direction.x) * degrees,
           y = std::asin(std::clamp(direction.z, -1.0, 1.0)) * degrees;
    if (!transformation) return grid->at(grid->wrappedLongitude(x), y);
    return transformation->Transform(1, &x, &y) ? grid->at(x, y) : 0.0;
  };
}

}  // namespace strata::bdam
