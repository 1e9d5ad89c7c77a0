// geometry.bdam's patch storage: a patch round-trips exactly through its compressed bytes, a real one (EGM96's geoid
// over a displaced triangle at Gale crater's place) in under half its plain size as the paper's did, extremes of the
// form too; damaged or truncated bytes give an error saying what is wrong, never a patch or a crash; a patch that
// breaks the form is refused before it is stored.
#include <gtest/gtest.h>

#include <gdal.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "grid_patch.hpp"
#include "patch_codec.hpp"

namespace strata::bdam {
namespace {

// EGM96's geoid (proj-data, 15' texels) at a longitude and latitude, m: the texel nearest.
class Geoid {
 public:
  Geoid() : dataset_(GDALOpen("/usr/share/proj/egm96_15.gtx", GA_ReadOnly)) {
    if (!dataset_) throw std::runtime_error("cannot open /usr/share/proj/egm96_15.gtx (proj-data)");
    GDALGetGeoTransform(dataset_, transform_);
  }
  ~Geoid() { GDALClose(dataset_); }
  double at(double lon, double lat) const {
    const int x = int(std::floor((lon - transform_[0]) / transform_[1]));
    const int y = int(std::floor((lat - transform_[3]) / transform_[5]));
    float value = 0.0f;
    if (GDALRasterIO(GDALGetRasterBand(dataset_, 1), GF_Read, x, y, 1, 1, &value, 1, 1, GDT_Float32, 0, 0) != CE_None)
      throw std::runtime_error("cannot read the geoid");
    return value;
  }

 private:
  GDALDatasetH dataset_;
  double transform_[6] = {};
};

std::size_t plainBytes(const DisplacedPatch& patch) {  // 2 x 12 bits and 32 bits a vertex, 32 bits an index
  return patch.vertices.size() * 7 + patch.indices.size() * 4;
}

TEST(PatchCodec, ARealPatchRoundTripsExactlyInUnderHalfItsPlainSize) {
  GDALAllRegister();
  const Geoid geoid;
  // 16 steps a side: 153 vertices, 256 triangles, a few hundred as the paper's patches; 10 degrees from Gale crater.
  const DisplacedPatch patch =
      gridPatch(16, [&](double b1, double b2) { return geoid.at(137.4 + 10.0 * b1, -4.6 - 10.0 * b2); });
  const std::vector<std::byte> stored = encodePatch(patch);
  EXPECT_EQ(decodePatch(stored), patch);
  const double ratio = double(stored.size()) / double(plainBytes(patch));
  std::printf("153 vertices, 256 triangles: %zu bytes stored of %zu plain (%.0f%%)\n", stored.size(), plainBytes(patch),
              100.0 * ratio);
  EXPECT_LT(ratio, 0.5) << "the paper's patches took under half their size [Cignoni et al. 2003, §4.4]";
}

TEST(PatchCodec, TheFormsExtremesRoundTrip) {
  DisplacedPatch corners;
  corners.vertices = {{0, 0, std::numeric_limits<std::int32_t>::min()},
                      {kBarycentricSteps, 0, std::numeric_limits<std::int32_t>::max()},
                      {0, kBarycentricSteps, 0}};
  corners.indices = {0, 1, 2, 2, 1, 0};
  for (const DisplacedPatch& patch : {DisplacedPatch{}, corners, gridPatch(64, [](double b1, double b2) {
                                        return 8848.0 * std::sin(40.0 * b1) * std::cos(33.0 * b2);
                                      })})
    EXPECT_EQ(decodePatch(encodePatch(patch)), patch);
}

TEST(PatchCodec, DamagedBytesSayWhatIsWrong) {
  const std::vector<std::byte> stored =
      encodePatch(gridPatch(8, [](double b1, double b2) { return 1000.0 * b1 * b2; }));
  for (std::size_t size = 0; size < stored.size(); ++size)
    EXPECT_THROW(decodePatch(std::span(stored).first(size)), PatchFormatError) << "truncated to " << size << " bytes";
  for (std::size_t at = 0; at < stored.size(); ++at) {
    std::vector<std::byte> damaged = stored;
    damaged[at] ^= std::byte(0x5a);
    EXPECT_THROW(decodePatch(damaged), PatchFormatError) << "byte " << at << " changed";
  }
  std::vector<std::byte> longer = stored;
  longer.push_back(std::byte(0));
  EXPECT_THROW(decodePatch(longer), PatchFormatError) << "a byte after the frame";
  try {
    decodePatch(std::span(stored).first(stored.size() / 2));
    ADD_FAILURE() << "half a patch decoded";
  } catch (const PatchFormatError& error) {
    EXPECT_NE(std::string(error.what()).find("truncated"), std::string::npos) << error.what();
  }
}

TEST(DisplacedVertex, QuantisesWithinTheTriangleAndKeepsTheHypotenuseOnIt) {
  for (int k = 0; k <= 1000; ++k) {
    const double b2 = k / 1000.0;
    const DisplacedVertex onTheHypotenuse = displacedVertex(1.0 - b2, b2, 0.0);
    EXPECT_EQ(onTheHypotenuse.b1 + onTheHypotenuse.b2, kBarycentricSteps) << b2;
  }
  EXPECT_EQ(displacedVertex(0.5, 0.25, 1234.567), (DisplacedVertex{2048, 1024, 123457}));
  EXPECT_THROW(displacedVertex(0.0, 0.0, 2.2e7), std::invalid_argument) << "22,000 km";
}

TEST(PatchCodec, APatchBreakingTheFormIsNotStored) {
  DisplacedPatch outside{{{4000, 100, 0}}, {}};
  EXPECT_THROW(encodePatch(outside), std::invalid_argument) << "b1 + b2 beyond the triangle";
  DisplacedPatch broken{{{0, 0, 0}, {1, 0, 0}}, {0, 1}};
  EXPECT_THROW(encodePatch(broken), std::invalid_argument) << "not whole triangles";
  DisplacedPatch dangling{{{0, 0, 0}}, {0, 0, 1}};
  EXPECT_THROW(encodePatch(dangling), std::invalid_argument) << "an index past the vertices";
}

}  // namespace
}  // namespace strata::bdam
