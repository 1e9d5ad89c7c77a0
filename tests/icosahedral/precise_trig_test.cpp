// shaders/strata/precise_trig.glsl run on the headless context at many float arguments, against the std::
// functions in double at the same arguments. Beside it, the test prints how far the driver's builtins are
// off at tiny arguments (NVIDIA's sin and cos are good to 4e-7 absolute only), without judging them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>

#include "compute_each.hpp"
#include "rendering.hpp"

namespace strata::icosahedral {
namespace {

constexpr int kFunctions = 5;
constexpr std::array<const char*, kFunctions> kNames = {"sin", "cos", "tan", "asin", "atan"};

// Errors are counted in units of 2^-23 |exact|, one to two ulp; the exact value is taken no smaller than
// the smallest normal float, below which GPUs flush to zero. The tolerances: precise_trig.glsl's worst error
// with IEEE float arithmetic, measured on the CPU over every float up to 4 (sin, cos, tan), every float of
// [-1, 1] (asin) and 3e8 random pairs (atan): 0.6, 0.6, 1.4, 1.7, 1.4; plus 1 for what a driver may do
// otherwise (fused multiply-adds, regrouping outside the precise parts); plus 1.5 where the function
// divides or takes a root (tan, asin, atan), which GLSL 4.50 lets be 2.5 ulp off rather than 0.5. No
// allowance for conditioning: the reduction by pi/2 is exact enough that cos next to its zeros and tan
// next to its poles stay good relatively. An NVIDIA H100 measured 0.53, 0.53, 1.62, 1.97, 1.32.
constexpr std::array<double, kFunctions> kTolerance = {2.0, 2.0, 4.0, 5.0, 4.0};

// Each argument (a, b) gives sin(a), cos(a), tan(a), asin(a) and atan(a, b): precise_trig.glsl's, then
// the builtins'.
const std::string kShader = test::eachElementShader("#include \"strata/precise_trig.glsl\"", "vec2", "float", R"(
  float a = arguments[i].x, b = arguments[i].y;
  float ours[5] = float[](preciseSin(a), preciseCos(a), preciseTan(a), preciseAsin(a), preciseAtan(a, b));
  float builtin[5] = float[](sin(a), cos(a), tan(a), asin(a), atan(a, b));
  for (uint f = 0u; f < 5u; ++f) {
    results[10u * i + f] = ours[f];
    results[10u * i + 5u + f] = builtin[f];
  }
)");

struct Results {
  std::array<float, kFunctions> ours, builtin;
};

std::vector<Results> evaluate(const std::vector<glm::vec2>& arguments) {
  test::headlessContext();
  const ShaderLibrary library;
  const ShaderProgram program(
      {{GL_COMPUTE_SHADER, "precise_trig_test.comp", library.expandText(kShader, "precise_trig_test.comp")}});
  return test::computeEach<Results>(program, arguments);
}

// Angles: zero, tiny ones, a logarithmic sweep from 1e-12 to 4, floats next to multiples of pi/4, an even
// sweep over [-4, 4], and sines next to 1. Each is paired with 1 and, negated, with -1 (atan's first and
// third quadrants, or second and fourth). Then atan's pairs: every quadrant and octant, ratios from 1e-30
// to 1e30, and the axes.
std::vector<glm::vec2> arguments() {
  std::vector<float> angles = {0.0f, 1e-30f, 1e-20f, 1e-10f, 1e-7f, 3e-6f, 0.5f, 1.0f, 2.0f, 4.0f};
  for (int i = 0; i <= 2000; ++i) angles.push_back(float(1e-12 * std::pow(4e12, i / 2000.0)));
  for (int j = 1; j <= 5; ++j) {
    float near = float(j * std::numbers::pi / 4.0);
    for (int step = 0; step < 4; ++step, near = std::nextafter(near, 0.0f)) angles.push_back(near);
    near = std::nextafter(float(j * std::numbers::pi / 4.0), 4.0f);
    for (int step = 0; step < 3; ++step, near = std::nextafter(near, 4.0f)) angles.push_back(near);
  }
  for (int i = 0; i <= 40000; ++i) angles.push_back(float(-4.0 + i / 5000.0));
  for (int i = 1; i <= 24; ++i) angles.push_back(float(1.0 - std::ldexp(1.0, -i)));
  std::vector<glm::vec2> pairs;
  for (const float a : angles) {
    pairs.emplace_back(a, 1.0f);
    pairs.emplace_back(-a, -1.0f);
  }
  for (int i = -120; i <= 120; ++i)
    for (const float x : {1e-5f, 1.0f, 3e4f})
      for (const glm::vec2 signs : {glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(-1, -1)})
        pairs.push_back(signs * glm::vec2(float(x * std::pow(10.0, i / 4.0)), x));
  for (int i = 0; i < 14400; ++i) {
    const double angle = i * std::numbers::pi / 7200.0;
    pairs.emplace_back(float(std::sin(angle)), float(std::cos(angle)));
  }
  for (const glm::vec2 pair : {glm::vec2(1, 2), glm::vec2(2, 1), glm::vec2(-1, 2), glm::vec2(2, -1), glm::vec2(0, 1),
                               glm::vec2(0, -1), glm::vec2(1, 0), glm::vec2(-1, 0), glm::vec2(1e-30f, -1)})
    pairs.push_back(pair);
  return pairs;
}

// The exact value at the float argument, or NaN outside where the function is judged: |a| <= 4 for sin,
// cos and tan (what subdivide_patches.comp meets), |a| <= 1 for asin; atan(0, b) left out for b <= 0,
// where GLSL does not say whether it is pi or -pi, or anything.
double exact(int function, glm::dvec2 argument) {
  const double a = argument.x, b = argument.y, nan = std::nan("");
  switch (function) {
    case 0: return std::abs(a) <= 4.0 ? std::sin(a) : nan;
    case 1: return std::abs(a) <= 4.0 ? std::cos(a) : nan;
    case 2: return std::abs(a) <= 4.0 ? std::tan(a) : nan;
    case 3: return std::abs(a) <= 1.0 ? std::asin(a) : nan;
    default: return a != 0.0 || b > 0.0 ? std::atan2(a, b) : nan;
  }
}

double units(float value, double exact) {
  return std::abs(double(value) - exact) / (std::ldexp(1.0, -23) * std::max(std::abs(exact), double(FLT_MIN)));
}

struct Worst {
  double units = 0.0;
  glm::vec2 at{};
  void add(double error, glm::vec2 argument) {
    if (!std::isnan(units) && !(error <= units)) units = error, at = argument;  // a NaN is the worst, and stays
  }
};

// Prints, beside the judged errors, the largest relative errors of the driver's builtins next to
// precise_trig.glsl's at tiny arguments (|a|, or for atan |a / b|), where an absolute error bound is no
// bound at all: from 1e-7 to 1e-5 (the angles subdivide_patches.comp takes sines of), below 1e-4, and
// everywhere.
void reportBuiltins(const std::vector<glm::vec2>& pairs, const std::vector<Results>& results) {
  const std::array<glm::dvec2, 3> ranges = {glm::dvec2(1e-7, 1e-5), glm::dvec2(0.0, 1e-4),
                                            glm::dvec2(0.0, std::numeric_limits<double>::infinity())};
  for (int f = 0; f < kFunctions; ++f) {
    std::array<Worst, 3> builtin, ours;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const double value = exact(f, pairs[i]);
      if (std::isnan(value)) continue;
      const double size = f == 4 ? std::abs(double(pairs[i].x) / pairs[i].y) : std::abs(pairs[i].x);
      for (std::size_t range = 0; range < ranges.size(); ++range) {
        if (size < ranges[range].x || size > ranges[range].y) continue;
        builtin[range].add(units(results[i].builtin[f], value), pairs[i]);
        ours[range].add(units(results[i].ours[f], value), pairs[i]);
      }
    }
    const double eps = std::ldexp(1.0, -23);
    std::printf(
        "%-4s worst relative error, builtin / precise: 1e-7 to 1e-5 %.2g / %.2g, below 1e-4 %.2g / %.2g, "
        "everywhere %.2g / %.2g\n",
        kNames[f], eps * builtin[0].units, eps * ours[0].units, eps * builtin[1].units, eps * ours[1].units,
        eps * builtin[2].units, eps * ours[2].units);
    ::testing::Test::RecordProperty(std::string("builtin_") + kNames[f] + "_tiny",
                                    std::to_string(eps * builtin[0].units));
    ::testing::Test::RecordProperty(std::string("precise_") + kNames[f] + "_tiny", std::to_string(eps * ours[0].units));
  }
}

TEST(PreciseTrig, IsGoodToAFewUlpRelativeEverywhere) {
  const std::vector<glm::vec2> pairs = arguments();
  const std::vector<Results> results = evaluate(pairs);
  for (int f = 0; f < kFunctions; ++f) {
    Worst worst;
    int judged = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const double value = exact(f, pairs[i]);
      if (std::isnan(value)) continue;
      worst.add(units(results[i].ours[f], value), pairs[i]);
      ++judged;
    }
    std::printf("precise %-4s: worst %.2f units of 2^-23 relative, at (%.9g, %.9g); %d arguments\n", kNames[f],
                worst.units, worst.at.x, worst.at.y, judged);
    EXPECT_LE(worst.units, kTolerance[f]) << kNames[f] << " at (" << worst.at.x << ", " << worst.at.y << ")";
  }
  reportBuiltins(pairs, results);
}

}  // namespace
}  // namespace strata::icosahedral
