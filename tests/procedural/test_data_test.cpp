// The GeoTIFFs strata-make-test-data writes (the test_data fixture) read back with GDAL at the expected
// size, CRS and nodata, and their pixels are the planet model's at PROJ's inverse of the pixel centres.
#include <gtest/gtest.h>

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <proj.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "planet_model.hpp"
#include "srgb_encoding.hpp"

namespace strata::test {
namespace {

constexpr double kMarsRadius = 3396190.0;
constexpr double kDegree = std::numbers::pi / 180.0;

struct Expected {
  const char* name;
  const char* crs;
  int width, height;
  bool coversAll = false;                 // no texel without data
  procedural::PlanetParameters planet{};  // what the observation saw
};

void PrintTo(const Expected& expected, std::ostream* out) { *out << expected.name; }

glm::dvec3 normalAt(double lon, double lat) {
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// Where an observation has data besides where PROJ inverts: the polar caps down to 45 degrees, the strip
// within 1.5 degrees of the great circle of a ground track inclined 60 degrees, ascending at longitude 10.
bool covered(const std::string& name, double lon, double lat) {
  if (name == "north") return lat >= 45.0 * kDegree;
  if (name == "south") return lat <= -45.0 * kDegree;
  if (name != "strip") return true;
  const double inclination = 60.0 * kDegree, node = 10.0 * kDegree;
  const glm::dvec3 orbitPole(std::sin(node) * std::sin(inclination), -std::cos(node) * std::sin(inclination),
                             std::cos(inclination));
  return std::abs(std::asin(glm::dot(orbitPole, normalAt(lon, lat)))) <= 1.5 * kDegree;
}

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

Dataset openRaster(const std::string& name, const char* product) {
  GDALAllRegister();
  const std::filesystem::path file = std::filesystem::path(STRATA_TEST_DATA_DIR) / (name + "-" + product + ".tif");
  return Dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

std::string proj4Of(const OGRSpatialReference& crs) {
  char* text = nullptr;
  crs.exportToProj4(&text);
  std::string proj4 = text ? text : "";
  CPLFree(text);
  return proj4;
}

// The CRS read back is the one written if PROJ maps points of the sphere alike through both, to a millimetre.
// Their texts differ (a polar stereographic with lat_ts 90 reads back with k=1), and GeoTIFF keeps no names.
void expectSameMapping(const std::string& actual, const std::string& wanted) {
  std::unique_ptr<PJ, decltype(&proj_destroy)> read(proj_create(nullptr, actual.c_str()), &proj_destroy),
      written(proj_create(nullptr, wanted.c_str()), &proj_destroy);
  ASSERT_TRUE(read && written) << actual;
  for (double lon = -170.0; lon < 180.0; lon += 50.0)
    for (double lat = -85.0; lat < 90.0; lat += 34.0) {
      const PJ_COORD point = proj_coord(lon * kDegree, lat * kDegree, 0.0, 0.0);
      const PJ_COORD a = proj_trans(read.get(), PJ_FWD, point), b = proj_trans(written.get(), PJ_FWD, point);
      EXPECT_NEAR(a.xy.x, b.xy.x, 1e-3) << actual << " and " << wanted << " at " << lon << "," << lat;
      EXPECT_NEAR(a.xy.y, b.xy.y, 1e-3) << actual << " and " << wanted << " at " << lon << "," << lat;
    }
}

void expectGeoreferencing(GDALDataset& dataset, const Expected& expected) {
  EXPECT_EQ(dataset.GetRasterXSize(), expected.width);
  EXPECT_EQ(dataset.GetRasterYSize(), expected.height);
  const OGRSpatialReference* crs = dataset.GetSpatialRef();
  ASSERT_NE(crs, nullptr);
  expectSameMapping(proj4Of(*crs), expected.crs);
  EXPECT_DOUBLE_EQ(crs->GetSemiMajor(), kMarsRadius);
  std::array<double, 6> geoTransform{};
  ASSERT_EQ(dataset.GetGeoTransform(geoTransform.data()), CE_None);
  EXPECT_EQ(geoTransform[2], 0.0);  // north up: no rotation, rows run south
  EXPECT_EQ(geoTransform[4], 0.0);
  EXPECT_LT(geoTransform[5], 0.0);
}

class TestData : public ::testing::TestWithParam<Expected> {};

TEST_P(TestData, HeightsAreFloat32MetresWithNodata) {
  const Expected& expected = GetParam();
  Dataset heights = openRaster(expected.name, "height");
  ASSERT_TRUE(heights) << "run the test_data fixture (strata-make-test-data) first";
  expectGeoreferencing(*heights, expected);
  ASSERT_EQ(heights->GetRasterCount(), 1);
  EXPECT_EQ(heights->GetRasterBand(1)->GetRasterDataType(), GDT_Float32);
  int hasNodata = 0;
  EXPECT_EQ(heights->GetRasterBand(1)->GetNoDataValue(&hasNodata), -32768.0);
  EXPECT_TRUE(hasNodata);
}

TEST_P(TestData, ColoursAreRgbaWithAnAlphaBand) {
  const Expected& expected = GetParam();
  Dataset colours = openRaster(expected.name, "color");
  ASSERT_TRUE(colours);
  expectGeoreferencing(*colours, expected);
  ASSERT_EQ(colours->GetRasterCount(), 4);
  for (int band = 1; band <= 4; ++band) EXPECT_EQ(colours->GetRasterBand(band)->GetRasterDataType(), GDT_Byte);
  EXPECT_EQ(colours->GetRasterBand(4)->GetColorInterpretation(), GCI_AlphaBand);
}

// Reads one pixel's height and RGBA.
std::pair<float, std::array<std::uint8_t, 4>> readPixel(GDALDataset& heights, GDALDataset& colours, int column,
                                                        int row) {
  float height = 0.0f;
  std::array<std::uint8_t, 4> rgba{};
  EXPECT_EQ(heights.GetRasterBand(1)->RasterIO(GF_Read, column, row, 1, 1, &height, 1, 1, GDT_Float32, 0, 0, nullptr),
            CE_None);
  EXPECT_EQ(colours.RasterIO(GF_Read, column, row, 1, 1, rgba.data(), 1, 1, GDT_Byte, 4, nullptr, 4, 4, 1, nullptr),
            CE_None);
  return {height, rgba};
}

TEST_P(TestData, PixelsAreThePlanetAtProjsInverseOfTheirCentres) {
  const Expected& expected = GetParam();
  Dataset heights = openRaster(expected.name, "height"), colours = openRaster(expected.name, "color");
  ASSERT_TRUE(heights && colours);
  const char* footprintItem = heights->GetMetadataItem("STRATA_SAMPLE_FOOTPRINT");
  ASSERT_NE(footprintItem, nullptr);
  const double footprint = std::stod(footprintItem);
  const procedural::PlanetModel planet(expected.planet, kMarsRadius);
  std::unique_ptr<PJ, decltype(&proj_destroy)> projection(proj_create(nullptr, expected.crs), &proj_destroy);
  ASSERT_TRUE(projection);
  const double toRadians = proj_angular_input(projection.get(), PJ_INV) ? kDegree : 1.0;
  std::array<double, 6> geoTransform{};
  heights->GetGeoTransform(geoTransform.data());
  int withData = 0, withoutData = 0;
  const int grid = 21;  // pixels across and down, evenly spread
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const int column = (2 * i + 1) * expected.width / (2 * grid), row = (2 * j + 1) * expected.height / (2 * grid);
      const PJ_COORD map = proj_coord((geoTransform[0] + (column + 0.5) * geoTransform[1]) * toRadians,
                                      (geoTransform[3] + (row + 0.5) * geoTransform[5]) * toRadians, 0.0, 0.0);
      const PJ_COORD lonlat = proj_trans(projection.get(), PJ_INV, map);
      const double lon = lonlat.lp.lam, lat = lonlat.lp.phi;
      const auto [height, rgba] = readPixel(*heights, *colours, column, row);
      if (!std::isfinite(lon) || !std::isfinite(lat) || !covered(expected.name, lon, lat)) {
        EXPECT_EQ(height, -32768.0f) << "pixel " << column << "," << row;
        EXPECT_EQ(rgba[3], 0) << "pixel " << column << "," << row;
        ++withoutData;
        continue;
      }
      const double reference = planet.height(normalAt(lon, lat), footprint);
      EXPECT_NEAR(height, reference, 0.01) << "pixel " << column << "," << row;  // Float32 keeps 1 mm at 12 km
      const std::array<std::uint8_t, 3> rgb = procedural::encodeSrgb8(planet.colour(reference));
      EXPECT_EQ((std::array<std::uint8_t, 4>{rgb[0], rgb[1], rgb[2], 255}), rgba) << "pixel " << column << "," << row;
      ++withData;
    }
  EXPECT_GT(withData, 20);
  if (!expected.coversAll) {
    EXPECT_GT(withoutData, 0) << "nodata should show somewhere";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Observations, TestData,
    ::testing::Values(
        Expected{"global", "+proj=longlat +R=3396190", 2048, 1024, true},
        Expected{"north", "+proj=stere +lat_0=90 +lat_ts=90 +R=3396190", 1024, 1024},
        Expected{"south", "+proj=stere +lat_0=-90 +lat_ts=-71 +R=3396190", 1024, 1024},
        Expected{"healpix", "+proj=healpix +R=3396190", 2048, 1024},
        Expected{"strip", "+proj=longlat +R=3396190", 910, 1365},
        // 25 cm texels at Gale crater's place, of the planet summed down to metre octaves
        Expected{"gale", "+proj=longlat +R=3396190", 1024, 4096, true, {.octaves = 24, .contourInterval = 1.0}}),
    [](const auto& test) { return std::string(test.param.name); });

// Every texel of `dataset` as `type`, `bands` interleaved.
template <class T>
std::vector<T> readAll(GDALDataset& dataset, GDALDataType type, int bands) {
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  std::vector<T> texels(std::size_t(width) * height * bands);
  EXPECT_EQ(dataset.RasterIO(GF_Read, 0, 0, width, height, texels.data(), width, height, type, bands, nullptr,
                             GSpacing(sizeof(T)) * bands, GSpacing(sizeof(T)) * bands * width, sizeof(T), nullptr),
            CE_None);
  return texels;
}

double srgbDecode(std::uint8_t level) {
  const double e = level / 255.0;
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

// The strip seen by a panchromatic camera (pipelines/chroma_fusion.yaml): on the strip's grid, the relative
// luminance of its colours (sRGB decoded, Rec. 709 weights) times 0.8, and nodata -1 where they have none.
TEST(PanchromaticStrip, IsTheStripColoursLuminanceAtFourFifths) {
  Dataset colours = openRaster("strip", "color"), luminance = openRaster("strip", "luminance");
  ASSERT_TRUE(colours && luminance) << "run the test_data fixture (strata-make-test-data) first";
  ASSERT_EQ(luminance->GetRasterCount(), 1);
  ASSERT_EQ(luminance->GetRasterBand(1)->GetRasterDataType(), GDT_Float32);
  expectGeoreferencing(*luminance, {"strip", "+proj=longlat +R=3396190", 910, 1365});
  int hasNodata = 0;
  EXPECT_EQ(luminance->GetRasterBand(1)->GetNoDataValue(&hasNodata), -1.0);
  EXPECT_TRUE(hasNodata);
  const std::vector<std::uint8_t> rgba = readAll<std::uint8_t>(*colours, GDT_Byte, 4);
  const std::vector<float> values = readAll<float>(*luminance, GDT_Float32, 1);
  int wrong = 0, withData = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::uint8_t* c = &rgba[i * 4];
    const double relative = 0.2126729 * srgbDecode(c[0]) + 0.7151522 * srgbDecode(c[1]) + 0.0721750 * srgbDecode(c[2]);
    const double expected = c[3] == 0 ? -1.0 : 0.8 * relative;
    wrong += std::abs(values[i] - expected) > 1e-6;
    withData += c[3] != 0;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(withData, 100000);
}

}  // namespace
}  // namespace strata::test
