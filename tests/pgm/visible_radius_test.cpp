// The least visible height of a frame, reduced on the GPU by plugins/geometry-pgm/pgm_least_radius.comp and read
// back without waiting (plugins/geometry-pgm/visible_radius.hpp), and the primary radius made from it
// ([Mahsman 2010, §3.4.1], method 2). Heights are random in [-8000, 21000) m, Mars's range, with one lower
// height planted at a random covered texel and large uncovered regions (+infinity). The minimum must come
// back to the bit, at screen size and at sizes that do not fill a workgroup.
#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <strata/gl/framebuffer.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/texture.hpp>

#include "reference_spheres.hpp"
#include "rendering.hpp"
#include "visible_radius.hpp"

namespace strata::pgm {
namespace {

constexpr float kUncovered = std::numeric_limits<float>::infinity();
constexpr double kMars = 3396000.0;  // m

struct Heights {
  Texture texture;
  float least;  // the planted minimum; kUncovered when nothing is covered
};

// A width x height R32F texture of random heights, uncovered above the diagonal band of the top-left
// corner and inside a disc (sky and a hole in the terrain), with `least` planted at a random covered texel.
Heights randomHeights(int width, int height, float least, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> heights(-8000.0f, 21000.0f);
  std::vector<float> texels(std::size_t(width) * std::size_t(height));
  std::vector<std::size_t> covered;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width, v = (y + 0.5) / height;
      const bool sky = u + v < 0.6, hole = (u - 0.7) * (u - 0.7) + (v - 0.6) * (v - 0.6) < 0.04;
      const std::size_t index = std::size_t(y) * std::size_t(width) + std::size_t(x);
      texels[index] = sky || hole ? kUncovered : heights(random);
      if (!sky && !hole) covered.push_back(index);
    }
  }
  texels[covered[std::uniform_int_distribution<std::size_t>(0, covered.size() - 1)(random)]] = least;
  Texture texture(GL_R32F, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, texels.data());
  return {std::move(texture), least};
}

Heights uncovered(int width, int height) {
  Texture texture(GL_R32F, width, height);
  glClearTexImage(texture.id(), 0, GL_RED, GL_FLOAT, &kUncovered);
  return {std::move(texture), kUncovered};
}

// What latest() gives once the GPU has finished everything.
std::optional<double> finished(VisibleRadius& radius) {
  glFinish();
  return radius.latest();
}

std::optional<double> leastOf(const Heights& heights) {
  if (heights.least == kUncovered) return std::nullopt;
  return heights.least;
}

class PgmVisibleRadius : public ::testing::Test {
 protected:
  void SetUp() override { test::headlessContext(); }
  const ShaderLibrary& library_ = test::pluginShaderLibrary();
};

TEST_F(PgmVisibleRadius, FindsThePlantedMinimumOnAScreen) {
  VisibleRadius radius(library_, 1);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Heights heights = randomHeights(1280, 720, -8123.4567f, seed);
    radius.reduce(heights.texture.id(), 1280, 720);
    EXPECT_EQ(finished(radius), std::optional<double>(-8123.4567f)) << seed;
  }
}

TEST_F(PgmVisibleRadius, FindsAPositiveMinimum) {
  const Heights heights = randomHeights(1280, 720, 12.5f, 4);
  std::vector<float> raised(std::size_t(1280) * 720);
  glGetTextureImage(heights.texture.id(), 0, GL_RED, GL_FLOAT, GLsizei(raised.size() * sizeof(float)), raised.data());
  for (float& texel : raised)
    if (texel != 12.5f && texel != kUncovered) texel = 13.0f + (texel + 8000.0f);
  glTextureSubImage2D(heights.texture.id(), 0, 0, 0, 1280, 720, GL_RED, GL_FLOAT, raised.data());
  VisibleRadius radius(library_, 1);
  radius.reduce(heights.texture.id(), 1280, 720);
  EXPECT_EQ(finished(radius), std::optional<double>(12.5f));
}

TEST_F(PgmVisibleRadius, HandlesSizesThatDoNotFillAWorkgroup) {
  VisibleRadius radius(library_, 1);
  const int sizes[][2] = {{1, 1}, {3, 5}, {1281, 721}, {17, 1}, {1, 33}};
  unsigned seed = 10;
  for (const auto& [width, height] : sizes) {
    const Heights heights = randomHeights(width, height, -8500.25f - float(seed), seed);
    radius.reduce(heights.texture.id(), width, height);
    EXPECT_EQ(finished(radius), leastOf(heights)) << width << " x " << height;
    ++seed;
  }
}

// Only the given part is reduced: a minimum just outside it is not seen.
TEST_F(PgmVisibleRadius, ReducesOnlyThePartAsked) {
  std::vector<float> texels(std::size_t(40) * 30, 100.0f);
  texels[std::size_t(29) * 40 + 39] = -1.0f;  // the last texel, outside 39 x 29
  texels[std::size_t(28) * 40 + 38] = 7.0f;   // the last texel inside
  Texture texture(GL_R32F, 40, 30);
  glTextureSubImage2D(texture.id(), 0, 0, 0, 40, 30, GL_RED, GL_FLOAT, texels.data());
  VisibleRadius radius(library_, 1);
  radius.reduce(texture.id(), 39, 29);
  EXPECT_EQ(finished(radius), std::optional<double>(7.0));
  radius.reduce(texture.id(), 40, 30);
  EXPECT_EQ(finished(radius), std::optional<double>(-1.0));
}

// In a multisampled frame (output.image's antialiasing) every sample counts: a height held by one sample of
// one pixel, the others higher, is the least.
TEST_F(PgmVisibleRadius, FindsAMinimumHeldByOneSampleOfOnePixel) {
  constexpr int kSamples = 4;
  const Framebuffer heights(64, 48, {GL_R32F}, 0, kSamples);
  const float cleared[4] = {300.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(heights.id(), GL_COLOR, 0, cleared);
  const ShaderProgram planting({{GL_VERTEX_SHADER, "strata/fullscreen.vert", library_.expand("strata/fullscreen.vert")},
                                {GL_FRAGMENT_SHADER, "planting.frag",
                                 "#version 450 core\nout float height;\nvoid main() { height = -42.5; }\n"}});
  heights.bind();
  glEnable(GL_SCISSOR_TEST);
  glScissor(37, 21, 1, 1);
  glEnable(GL_SAMPLE_MASK);
  glSampleMaski(0, 1u << 2);
  planting.use();
  const FullscreenTriangle triangle;
  triangle.draw();
  glDisable(GL_SAMPLE_MASK);
  glDisable(GL_SCISSOR_TEST);
  VisibleRadius radius(library_, kSamples);
  radius.reduce(heights.color(0).id(), 64, 48);
  EXPECT_EQ(finished(radius), std::optional<double>(-42.5));
}

TEST_F(PgmVisibleRadius, GivesNothingBeforeTheFirstReductionOrWhenNothingIsCovered) {
  VisibleRadius radius(library_, 1);
  EXPECT_EQ(finished(radius), std::nullopt);
  const Heights covered = randomHeights(1280, 720, -8100.0f, 5);
  radius.reduce(covered.texture.id(), 1280, 720);
  EXPECT_EQ(finished(radius), std::optional<double>(-8100.0));
  const Heights sky = uncovered(1280, 720);
  radius.reduce(sky.texture.id(), 1280, 720);
  EXPECT_EQ(finished(radius), std::nullopt);
}

// Without glFinish, latest() may only give what a finished reduction gave, in the order they were made:
// nothing or the first before the second, never a value of neither. After glFinish, the second.
TEST_F(PgmVisibleRadius, ReadsBackWithoutWaiting) {
  const Heights first = randomHeights(1280, 720, -8001.0f, 6), second = randomHeights(1280, 720, -8002.0f, 7);
  for (bool warm : {false, true}) {
    SCOPED_TRACE(warm);
    VisibleRadius radius(library_, 1);
    if (warm) {  // a finished value is kept while the next one runs
      radius.reduce(first.texture.id(), 1280, 720);
      ASSERT_EQ(finished(radius), leastOf(first));
    }
    radius.reduce(first.texture.id(), 1280, 720);
    radius.reduce(second.texture.id(), 1280, 720);
    bool sawSecond = false;
    for (int poll = 0; poll < 1000; ++poll) {
      const std::optional<double> value = radius.latest();
      if (sawSecond)
        ASSERT_EQ(value, leastOf(second)) << poll;
      else if (warm)
        ASSERT_TRUE(value == leastOf(first) || value == leastOf(second)) << poll;
      else
        ASSERT_TRUE(!value || value == leastOf(first) || value == leastOf(second)) << poll;
      sawSecond = value == leastOf(second);
    }
    EXPECT_EQ(finished(radius), leastOf(second));
  }
}

// More reductions in flight than slots: the oldest unread ones are dropped, the newest still arrives.
TEST_F(PgmVisibleRadius, KeepsTheNewestWhenTheRingComesRound) {
  VisibleRadius radius(library_, 1);
  std::vector<Heights> frames;
  for (unsigned frame = 0; frame < 7; ++frame)
    frames.push_back(randomHeights(320, 180, -8000.5f - float(frame), 20 + frame));
  for (const Heights& heights : frames) radius.reduce(heights.texture.id(), 320, 180);
  EXPECT_EQ(finished(radius), leastOf(frames.back()));
}

TEST_F(PgmVisibleRadius, PrimaryRadiusFallsBackToTheMinimumSphereAndStaysBelowTheEye) {
  constexpr double kLowest = -8200.0, kEye = kMars + 5000.0;
  EXPECT_EQ(primaryRadius(std::nullopt, kMars, kLowest, kEye), kMars + kLowest);
  EXPECT_EQ(primaryRadius(-120.0, kMars, kLowest, kEye), kMars - 120.0);
  EXPECT_EQ(primaryRadius(4999.0, kMars, kLowest, kEye), kMars + 4999.0);
  EXPECT_EQ(primaryRadius(6000.0, kMars, kLowest, kEye), clampPrimaryRadius(kMars + 6000.0, kEye));
  EXPECT_LT(primaryRadius(6000.0, kMars, kLowest, kEye), kEye);
  EXPECT_LT(primaryRadius(std::nullopt, kMars, kLowest, kMars - 9000.0), kMars - 9000.0);  // eye below the lowest
}

}  // namespace
}  // namespace strata::pgm
