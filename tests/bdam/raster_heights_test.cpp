// `strata build-bdam`'s heights from rasters of any projection: EGM96's geoid (proj-data) as its longitude/latitude
// grid and as GDAL warps it to a south polar stereographic cap give the same heights about the pole and across the
// antimeridian; the global grid wraps east and west; a place the cap does not cover is the sphere.
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "raster_heights.hpp"

namespace strata::bdam {
namespace {

glm::dvec3 direction(double lon, double lat) {
  const glm::dvec2 r = glm::radians(glm::dvec2(lon, lat));
  return {std::cos(r.y) * std::cos(r.x), std::cos(r.y) * std::sin(r.x), std::sin(r.y)};
}

// The geoid south of about 58 S as a polar stereographic GeoTIFF of 5 km texels (finer than its 28 km), by gdalwarp.
std::string stereographicGeoid(const std::string& path) {
  GDALAllRegister();
  std::vector<std::string> arguments = {"-t_srs",   "+proj=stere +lat_0=-90 +lat_ts=-71 +datum=WGS84",
                                        "-te",      "-3500000",
                                        "-3500000", "3500000",
                                        "3500000",  "-tr",
                                        "5000",     "5000",
                                        "-r",       "cubic",
                                        "-of",      "GTiff"};
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::unique_ptr<GDALWarpAppOptions, void (*)(GDALWarpAppOptions*)> options(
      GDALWarpAppOptionsNew(argv.data(), nullptr), GDALWarpAppOptionsFree);
  GDALDatasetH source = GDALOpen("/usr/share/proj/egm96_15.gtx", GA_ReadOnly);
  GDALDatasetH warped = GDALWarp(path.c_str(), nullptr, 1, &source, options.get(), nullptr);
  GDALClose(warped);
  GDALClose(source);
  return path;
}

TEST(RasterHeights, AStereographicCapAgreesWithTheLongitudeLatitudeGrid) {
  const RasterHeights grid("/usr/share/proj/egm96_15.gtx");
  const RasterHeights cap(stereographicGeoid(::testing::TempDir() + "geoid-south.tif"));
  EXPECT_EQ(cap.bodyRadius(), 6378137.0);
  EXPECT_DOUBLE_EQ(cap.texelSize(6378137.0), 5000.0);
  const HeightAt fromGrid = grid.sampler(), fromCap = cap.sampler();
  for (const double lat : {-89.99, -85.0, -75.0, -62.0})
    for (const double lon : {-179.99, 179.99, 180.0, -120.0, 0.0, 45.5, 137.4}) {
      // The cap's texels are cubic interpolations of the grid's, both read bilinearly: they differ where the geoid
      // bends within a 28 km texel, by 2.5 cm at most at these places; 5 cm allowed, a thousandth of its relief.
      EXPECT_NEAR(fromCap(direction(lon, lat)), fromGrid(direction(lon, lat)), 0.05) << lon << ", " << lat;
    }
  EXPECT_EQ(fromCap(direction(10.0, 0.0)), 0.0) << "the equator lies off the cap: the sphere";
  std::remove((::testing::TempDir() + "geoid-south.tif").c_str());
}

TEST(RasterHeights, AGlobalGridWrapsEastAndWest) {
  const HeightAt heights = RasterHeights("/usr/share/proj/egm96_15.gtx").sampler();
  for (const double lat : {-30.0, 0.0, 64.0}) {
    const double east = heights(direction(179.999999, lat)), west = heights(direction(-179.999999, lat));
    EXPECT_NEAR(east, west, 1e-3) << "at " << lat;  // the seam is between two texel centres, not at a border
  }
}

}  // namespace
}  // namespace strata::bdam
