// shaders/strata/surface_buffer.glsl run on the headless context: the shading normal's octahedral encoding
// read back, or the sphere's where the buffer stores none, what says a sample is on the body, and the sphere's
// normal from offsets to the reference, against double.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/surface_buffer.hpp>

#include "compute_each.hpp"
#include "rendering.hpp"

namespace strata::test {
namespace {

// Each argument: a unit vector and an offset from the reference (xy). Each result: the vector written as
// a surface sample and read back, whether that sample is on the body, whether the clear value is, and the
// sphere's normal at the offset.
const std::string kShader = eachElementShader(R"(#include "strata/surface_buffer.glsl"
struct Argument { vec4 normal; vec4 offset; };
struct Result { vec4 normal; vec4 sphereNormal; };
uniform vec4 referenceTrig;
uniform float noSurface;  // SurfaceBuffer::kNoSurface)",
                                              "Argument", "Result", R"(
  vec4 written = surfaceSample(arguments[i].offset.xy, arguments[i].normal.xyz);
  vec3 sphere = sphereNormalFromReference(arguments[i].offset.xy, referenceTrig);
  bool cleared = onSurface(vec4(noSurface, 0.0, 0.0, 0.0)) || onSurface(vec4(noSurface, 0.0, 0.0, 1.0));
  results[i].normal = vec4(shadingNormalOf(written, vec3(0.0)), onSurface(written) && !cleared ? 1.0 : 0.0);
  vec4 withoutNormal = vec4(written.xy, 0.0, 1.0);  // as an RG32F buffer reads
  bool sphereRead = onSurface(withoutNormal) && shadingNormalOf(withoutNormal, sphere) == sphere;
  results[i].sphereNormal = vec4(sphere, sphereRead && kNoSurface == noSurface ? 1.0 : 0.0);
)");

struct Argument {
  glm::vec4 normal, offset;
};
struct Result {
  glm::vec4 normal, sphereNormal;
};

std::vector<Result> evaluate(const std::vector<Argument>& arguments, glm::dvec2 reference) {
  headlessContext();
  const ShaderLibrary library;
  const ShaderProgram program(
      {{GL_COMPUTE_SHADER, "surface_buffer_test.comp", library.expandText(kShader, "surface_buffer_test.comp")}});
  program.set("referenceTrig", sinesAndCosines(reference));
  program.set("noSurface", SurfaceBuffer::kNoSurface);
  return computeEach<Result>(program, arguments);
}

// Unit vectors: the axes and their diagonals (the octahedron's corners and edges, where the encoding folds),
// vectors a float's step from the poles, and random ones; each paired with an offset from 1e-9 rad (6 mm on
// Earth) to half a turn.
std::vector<Argument> arguments() {
  std::vector<glm::dvec3> normals;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) normals.emplace_back(x, y, z);
  for (double tiny : {1e-7, 1e-4}) normals.insert(normals.end(), {{tiny, 0, 1}, {0, -tiny, -1}, {tiny, tiny, -1}});
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 4000; ++i) normals.emplace_back(gauss(random), gauss(random), gauss(random));
  std::uniform_real_distribution<double> exponent(-9.0, std::log10(std::numbers::pi)), sign(-1.0, 1.0);
  std::vector<Argument> arguments;
  for (const glm::dvec3& n : normals) {
    const glm::dvec2 offset(std::copysign(std::pow(10.0, exponent(random)), sign(random)),
                            0.5 * std::copysign(std::pow(10.0, exponent(random)), sign(random)));
    arguments.push_back({glm::vec4(glm::vec3(glm::normalize(n)), 0.0f), glm::vec4(glm::vec2(offset), 0.0f, 0.0f)});
  }
  return arguments;
}

// The octahedral encoding in float, offset by 2 (a step of 2.4e-7 at most), stretches the sphere by up to
// about 2 along some directions: 1e-6 rad bounds the angle between a normal and what is read back, 0.02
// degrees' shading at most a thousandth of a level of 8 bits. llvmpipe: under 2.5e-7.
constexpr double kNormalAngle = 1e-6;
// The sphere's normal: float components hold 6e-8; the reference's sines and cosines and the offsets' are
// each rounded once and added in four products: 3e-7 bounds every component at every offset. llvmpipe: 1.6e-7
// at worst (lon 137.4, lat -4.6).
constexpr double kSphereNormal = 3e-7;

TEST(SurfaceBufferGlsl, ShadingNormalsReadBackOrAreTheSpheresAndEverySampleIsOnTheBody) {
  const std::vector<Argument> input = arguments();
  const std::vector<Result> output = evaluate(input, glm::dvec2(0.0));
  for (std::size_t i = 0; i < input.size(); ++i) {
    const glm::dvec3 n(input[i].normal), back(output[i].normal);
    const double angle = std::atan2(glm::length(glm::cross(n, back)), glm::dot(n, back));
    EXPECT_LE(angle, kNormalAngle) << n.x << "," << n.y << "," << n.z;
    EXPECT_EQ(output[i].normal.w, 1.0f) << "on the body, and the clear value off it";
    EXPECT_EQ(output[i].sphereNormal.w, 1.0f) << "a buffer without normals gives the sphere's, on the body";
  }
}

TEST(SurfaceBufferGlsl, TheSphereNormalFromOffsetsAgreesWithDoubleAnywhere) {
  const std::vector<Argument> input = arguments();
  for (const glm::dvec2 degrees : {glm::dvec2(0, 0), glm::dvec2(137.4, -4.6), glm::dvec2(-179.99, 45),
                                   glm::dvec2(10, 89.9999), glm::dvec2(-60, -90)}) {
    const glm::dvec2 reference = glm::radians(degrees);
    const std::vector<Result> output = evaluate(input, reference);
    double worst = 0.0;
    for (std::size_t i = 0; i < input.size(); ++i) {
      glm::dvec2 lonlat = reference + glm::dvec2(input[i].offset);
      lonlat.y = std::clamp(lonlat.y, -0.5 * std::numbers::pi, 0.5 * std::numbers::pi);
      if (lonlat.y != reference.y + double(input[i].offset.y)) continue;  // beyond a pole: no point
      const glm::dvec3 error = glm::dvec3(output[i].sphereNormal) - unitNormal(lonlat.x, lonlat.y);
      worst = std::max({worst, std::abs(error.x), std::abs(error.y), std::abs(error.z)});
    }
    EXPECT_LE(worst, kSphereNormal) << "reference " << degrees.x << ", " << degrees.y;
  }
}

}  // namespace
}  // namespace strata::test
