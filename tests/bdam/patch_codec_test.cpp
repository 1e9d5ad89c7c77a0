// geometry.bdam's patch storage: a patch round-trips exactly through its compressed bytes, a real one (EGM96's geoid
// over a displaced triangle at Gale crater's place) in under half its plain size as the paper's did, extremes of the
// form too; damaged or truncated bytes give an error saying what is wrong, never a patch or a crash; a patch that
// breaks the form is refused before it is stored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "cube_bintree.hpp"
#include "leaf_patch.hpp"
#include "patch_codec.hpp"
#include "raster_heights.hpp"

namespace strata::bdam {
namespace {

std::size_t plainBytes(const DisplacedPatch& patch) {  // 2 x 12 bits and 32 bits a vertex, 32 bits an index
  return patch.vertices.size() * 7 + patch.indices.size() * 4;
}

constexpr double kMars = 3396190.0;  // m

// A leaf patch of `divisions` steps a side about Gale crater's place, on `heights`.
DisplacedPatch patchAtGale(int level, int divisions, const HeightAt& heights) {
  const glm::dvec2 gale = glm::radians(glm::dvec2(137.4, -4.6));
  const glm::dvec3 direction(std::cos(gale.y) * std::cos(gale.x), std::cos(gale.y) * std::sin(gale.x),
                             std::sin(gale.y));
  return leafPatch(nodeContaining(direction, level), kMars, heights, divisions);
}

TEST(PatchCodec, ARealPatchRoundTripsExactlyInUnderHalfItsPlainSize) {
  const HeightAt geoid = RasterHeights("/usr/share/proj/egm96_15.gtx").sampler();
  // 16 steps a side: 153 vertices, 256 triangles, a few hundred as the paper's patches; level 10, 170 km a side.
  const DisplacedPatch patch = patchAtGale(10, 16, geoid);
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
  const HeightAt ridges = [](const glm::dvec3& d) { return 8848.0 * std::sin(4000.0 * d.x) * std::cos(3300.0 * d.y); };
  for (const DisplacedPatch& patch : {DisplacedPatch{}, corners, patchAtGale(6, 64, ridges)})
    EXPECT_EQ(decodePatch(encodePatch(patch)), patch);
}

// Every truncation fails, and every changed byte either fails or leaves the patch as it was (a bit of the
// compressed form's own bookkeeping that zstd's decoder does not read: the content, checksummed, is unchanged).
TEST(PatchCodec, DamagedBytesSayWhatIsWrong) {
  const DisplacedPatch patch = patchAtGale(12, 8, [](const glm::dvec3& d) { return 1.0e6 * d.x * d.y; });
  const std::vector<std::byte> stored = encodePatch(patch);
  for (std::size_t size = 0; size < stored.size(); ++size)
    EXPECT_THROW(decodePatch(std::span(stored).first(size)), PatchFormatError) << "truncated to " << size << " bytes";
  int unread = 0;
  for (std::size_t at = 0; at < stored.size(); ++at) {
    std::vector<std::byte> damaged = stored;
    damaged[at] ^= std::byte(0x5a);
    try {
      EXPECT_EQ(decodePatch(damaged), patch) << "byte " << at << " changed, and the patch with it, unnoticed";
      ++unread;
    } catch (const PatchFormatError&) {
    }
  }
  std::printf("%zu bytes: %d changes of one byte unread by the decoder, the rest refused\n", stored.size(), unread);
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
