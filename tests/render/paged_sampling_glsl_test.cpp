// shaders/strata/anisotropic_taps.glsl and paged_texture.glsl's wrappedAround run on the headless context: how
// many taps a footprint takes and how wide each is, and a texel address taken into a raster's one period
// around the body, against integer arithmetic in C++.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>

#include "compute_each.hpp"
#include "rendering.hpp"

namespace strata::test {
namespace {

// Each argument: a footprint's steps (texels, xy and zw), a texel address (whole in .x, part in .y) and the
// raster's width (.z). Each result: the taps' count and width, and the address wrapped (whole, part).
const std::string kShader = eachElementShader(R"(#include "strata/paged_texture.glsl"
struct Argument { vec4 steps; ivec4 address; vec4 part; };
struct Result { vec4 taps; ivec4 wrapped; vec4 part; };)",
                                              "Argument", "Result", R"(
  Argument a = arguments[i];
  AnisotropicTaps taps = anisotropicTaps(a.steps.xy, a.steps.zw);
  TexelAddress wrapped = wrappedAround(TexelAddress(a.address.xy, a.part.xy), a.address.z);
  results[i] = Result(vec4(float(taps.count), taps.width, 0.0, 0.0), ivec4(wrapped.whole, 0, 0), vec4(wrapped.part, 0, 0));
)");

struct Argument {
  glm::vec4 steps;
  glm::ivec4 address;
  glm::vec4 part;
};
struct Result {
  glm::vec4 taps;
  glm::ivec4 wrapped;
  glm::vec4 part;
};

std::vector<Result> evaluate(const std::vector<Argument>& arguments) {
  headlessContext();
  const ShaderLibrary library;
  const ShaderProgram program(
      {{GL_COMPUTE_SHADER, "paged_sampling_test.comp", library.expandText(kShader, "paged_sampling_test.comp")}});
  return computeEach<Result>(program, arguments);
}

Argument footprint(glm::vec2 stepX, glm::vec2 stepY) { return {{stepX, stepY}, {0, 0, 1, 0}, {}}; }

// A magnified footprint, however stretched, takes one bilinear tap at the finest level: taps closer together
// than a texel would sample the same texels. A minified one takes as many as it is longer than wide, up to 8,
// each as wide as its minor axis or the major axis's share.
TEST(PagedSamplingGlsl, TapsFollowTheFootprintAndAMagnifiedOneTakesOne) {
  struct Case {
    Argument argument;
    float count, width;
  };
  const std::vector<Case> cases{
      {footprint({0.01f, 0.0f}, {0.0f, 0.002f}), 1, 1},  // a view close to the raster, grazing it
      {footprint({0.9f, 0.0f}, {0.0f, 0.1f}), 1, 1},     // still within a texel
      {footprint({0.0f, 1.0f}, {1.0f, 0.0f}), 1, 1},     // a texel a pixel
      {footprint({1.4f, 0.0f}, {0.0f, 1.0f}), 1, 1.4f},  // half again as long as wide: one tap, as hardware
      {footprint({4.0f, 0.0f}, {0.0f, 2.0f}), 2, 2},
      {footprint({0.0f, 8.0f}, {0.5f, 0.0f}), 8, 1},            // the minor axis below a texel counts as one
      {footprint({20.0f, 0.0f}, {0.0f, 1.0f}), 8, 2.5f},        // longer than 8 taps cover: each wider
      {footprint({3.0f, 3.0f}, {-1.0f, 1.0f}), 3, 1.4142135f},  // a rotated footprint: its own axes
  };
  std::vector<Argument> arguments;
  for (const Case& c : cases) arguments.push_back(c.argument);
  const std::vector<Result> results = evaluate(arguments);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(results[i].taps.x, cases[i].count) << "case " << i;
    EXPECT_NEAR(results[i].taps.y, cases[i].width, 1e-5f * cases[i].width) << "case " << i;
  }
}

// Addresses up to three periods either side of a raster's one, whose part carries up to two texels either way,
// for widths a JPEG, a HEALPix strip and a large raster have: each lands in [0, width), the same texel modulo the
// width, its part in [0, 1).
TEST(PagedSamplingGlsl, WrappingKeepsTheTexelModuloTheWidth) {
  std::vector<Argument> arguments;
  for (const int width : {2048, 6144, 86400, 1 << 22})
    for (const std::int64_t period : {-3, -1, 0, 1, 2})
      for (const int offset : {0, 1, 2, 7, width / 2, width - 2, width - 1})
        for (const float part : {-2.0f, -1.0f, -0.25f, 0.0f, 0.5f, 1.0f, 1.75f})
          arguments.push_back({{}, {int(period * width + offset), 5, width, 0}, {part, 0.25f, 0, 0}});
  const std::vector<Result> results = evaluate(arguments);
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const Argument& a = arguments[i];
    const int width = a.address.z;
    const std::int64_t texel = std::int64_t(a.address.x) + std::int64_t(std::floor(a.part.x));
    const std::int64_t expected = ((texel % width) + width) % width;
    EXPECT_EQ(results[i].wrapped.x, expected) << "texel " << texel << " of a raster " << width << " wide";
    EXPECT_EQ(results[i].wrapped.y, 5);
    EXPECT_EQ(results[i].part.x, a.part.x - std::floor(a.part.x));
    EXPECT_EQ(results[i].part.y, 0.25f);
  }
}

}  // namespace
}  // namespace strata::test
