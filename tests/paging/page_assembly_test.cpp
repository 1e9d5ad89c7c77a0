// Assembling a page with its border (core/paging/include/paging/page_assembly.hpp) from a source whose texels say
// where they are: value = level column, coverage = level row + 1. A source may have one column it cannot
// read, as a damaged tile would.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <strata/plugin/healpix_pyramid.hpp>

#include "paging/page_assembly.hpp"

namespace strata {
namespace {

class PositionSource : public PageSource {
 public:
  PositionSource(int width, int height, int unreadableColumn = -1)
      : pyramid_(width, height), unreadableColumn_(unreadableColumn) {}
  const PagePyramid& pyramid() const override { return pyramid_; }
  PageFormat format() const override { return PageFormat::Values; }
  std::string name() const override { return "positions"; }
  void read(const LevelWindow& window, std::span<std::byte> texels) const override {
    EXPECT_GE(window.x, 0);
    EXPECT_GE(window.y, 0);
    EXPECT_LE(window.x + window.width, pyramid_.levelWidth(window.level));
    EXPECT_LE(window.y + window.height, pyramid_.levelHeight(window.level));
    if (unreadableColumn_ >= window.x && unreadableColumn_ < window.x + window.width)
      throw std::runtime_error("column " + std::to_string(unreadableColumn_) + " is damaged");
    for (int y = 0; y < window.height; ++y)
      for (int x = 0; x < window.width; ++x) {
        const std::array<float, 2> texel{float(window.x + x), float(window.y + y + 1)};
        std::memcpy(texels.data() + (std::size_t(y) * window.width + x) * kPageTexelBytes, texel.data(), 8);
      }
  }

 private:
  PagePyramid pyramid_;
  int unreadableColumn_;
};

struct Slot {
  std::vector<std::byte> bytes = std::vector<std::byte>(kPageBytes);
  // The level column and row slot texel (i, j) was filled from.
  std::array<int, 2> at(int i, int j) const {
    std::array<float, 2> texel{};
    std::memcpy(texel.data(), bytes.data() + (std::size_t(j) * kPageSide + i) * kPageTexelBytes, 8);
    return {int(texel[0]), int(texel[1]) - 1};
  }
};

// Twelve HEALPix faces side by side (strata/plugin/healpix_pyramid.hpp), whose texels say where they are.
class FaceStripSource final : public PositionSource {
 public:
  explicit FaceStripSource(int nside)
      : PositionSource(12 * nside, nside), nside_(nside), pyramid_(healpix::stripPyramid(nside)) {}
  const PagePyramid& pyramid() const override { return pyramid_; }
  LevelWindow gridOf(const PageKey& key) const override {
    const int side = nside_ >> key.level;
    return {key.level, key.column * kPagePayload / side * side, 0, side, side};
  }
  std::optional<glm::ivec2> texelBeside(const PageKey& key, glm::ivec2 texel) const override {
    const int side = nside_ >> key.level;
    return healpix::texelAcross(side, key.column * kPagePayload / side, texel);
  }

 private:
  int nside_;
  PagePyramid pyramid_;
};

Slot assembled(const PageSource& source, PageKey key, bool wrapX) {
  Slot slot;
  paging::assemblePage(source, key, wrapX, slot.bytes);
  return slot;
}

TEST(PageAssembly, TheBorderHoldsTheNeighboursEdgeTexels) {
  const PositionSource source(2000, 1600);
  const Slot slot = assembled(source, {0, 1, 1}, false);
  EXPECT_EQ(slot.at(1, 1), (std::array{512, 512}));        // the payload's first texel
  EXPECT_EQ(slot.at(0, 0), (std::array{511, 511}));        // the north-west neighbour's corner
  EXPECT_EQ(slot.at(513, 513), (std::array{1024, 1024}));  // the south-east neighbour's corner
}

// Beyond a face's edge the border holds the neighbouring face's texels across that edge on the sphere;
// beyond a page's edge inside the face, the face's own.
TEST(PageAssembly, BordersAcrossHealpixFaceEdgesComeFromTheNeighbouringFace) {
  const FaceStripSource source(1024);
  for (const PageKey key : {PageKey{0, 2, 0}, PageKey{0, 13, 1}, PageKey{1, 1, 0}, PageKey{1, 11, 0}}) {
    const Slot slot = assembled(source, key, false);
    const LevelWindow face = source.gridOf(key);
    for (int j = 0; j < kPageSide; ++j)
      for (int i = 0; i < kPageSide; ++i) {
        const glm::ivec2 at(key.column * kPagePayload + i - 1, key.row * kPagePayload + j - 1);
        const bool inside = at.x >= face.x && at.x < face.x + face.width && at.y >= 0 && at.y < face.height;
        const glm::ivec2 expected = inside ? at : healpix::texelAcross(face.width, face.x / face.width, at);
        ASSERT_EQ(slot.at(i, j), (std::array{expected.x, expected.y}))
            << "level " << key.level << " page " << key.column << ", " << key.row << " slot texel " << i << ", " << j;
      }
  }
}

TEST(PageAssembly, EdgesOfTheLevelAreClampedWithoutWrap) {
  const PositionSource source(2000, 1600);
  const Slot first = assembled(source, {0, 0, 0}, false);
  EXPECT_EQ(first.at(0, 0), (std::array{0, 0}));
  const Slot last = assembled(source, {0, 3, 3}, false);  // 464 x 64 texels of payload
  EXPECT_EQ(last.at(464, 64), (std::array{1999, 1599}));
  EXPECT_EQ(last.at(465, 65), (std::array{1999, 1599}));
  EXPECT_EQ(last.at(513, 513), (std::array{1999, 1599}));
}

TEST(PageAssembly, AWrappingLevelBordersItsEastAndWestEdges) {
  const PositionSource source(2000, 1000);
  EXPECT_EQ(assembled(source, {0, 0, 0}, true).at(0, 5), (std::array{1999, 4}));
  EXPECT_EQ(assembled(source, {0, 3, 0}, true).at(465, 5), (std::array{0, 4}));
  const Slot whole = assembled(source, {2, 0, 0}, true);  // 500 x 250: one page holds the level
  EXPECT_EQ(whole.at(0, 1), (std::array{499, 0}));
  EXPECT_EQ(whole.at(501, 1), (std::array{0, 0}));
}

TEST(PageAssembly, AnUnreadableNeighbourLeavesTheBorderClampedToThePagesOwnEdge) {
  const PositionSource source(2000, 1600, 1024);  // the first column of page column 2
  const Slot slot = assembled(source, {0, 1, 1}, false);
  EXPECT_EQ(slot.at(0, 0), (std::array{512, 512}));        // no longer the north-west neighbour's corner
  EXPECT_EQ(slot.at(256, 256), (std::array{767, 767}));    // the payload as ever
  EXPECT_EQ(slot.at(513, 513), (std::array{1023, 1023}));  // no longer the south-east neighbour's corner
}

TEST(PageAssembly, AnUnreadablePageThrows) {
  const PositionSource source(2000, 1600, 700);
  Slot slot;
  EXPECT_THROW(paging::assemblePage(source, {0, 1, 1}, false, slot.bytes), std::runtime_error);
}

}  // namespace
}  // namespace strata
