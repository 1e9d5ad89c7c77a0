// plugins/geometry-healpix/healpix_offset.glsl run in float on the headless context, against
// strata/plugin/healpix.hpp's inverse in double: the unit vector of a point of a node of a base face minus that of the
// node's centre, for nodes of every face from the whole face (level 0) down to level 26 (2^-26 of a face, about 10 cm
// on Earth), at random places, at the poles, at the corners and astride the boundary between the polar caps and the
// equatorial zone, where the inverse changes its formula.
//
// The frame's terms are rounded to float, each by 6e-8 of itself, and each enters the difference as a
// factor: the difference is then good to a few times 6e-8 of itself, whatever its size. Measured on
// llvmpipe over 34,560 probes: 5.0e-7 at worst; kTolerance is twice that. Two forms failed here first and
// show what the test catches: the cap's height change written with 2 - |a + a'| lost a quarter of itself
// within 2^-22 of a pole, and the ring number's change across the boundary formed as (1 - a') - 1 rounded
// to nothing, turning the longitude by the whole offset.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/healpix.hpp>

#include "healpix_frame.hpp"
#include "rendering.hpp"

namespace strata::healpix {
namespace {

constexpr double kTolerance = 1e-6;  // of the difference's length

const char* kProbe = R"(#version 450 core
#include "strata/precise_trig.glsl"
#include "geometry-healpix/healpix_offset.glsl"
layout(local_size_x = 64) in;
struct Probe { HealpixFrame frame; vec4 offset; };
layout(std430, binding = 0) readonly buffer Probes { Probe probes[]; };
layout(std430, binding = 1) writeonly buffer Offsets { vec4 offsets[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(probes.length())) return;
  offsets[i] = vec4(healpixOffset(probes[i].frame, probes[i].offset.xy), 0.0);
}
)";

struct Probe {
  HealpixFrame frame;
  glm::vec4 offset;  // xy: (dx, dy) from the frame's reference
};

// A node of a base face, probed on a 5 x 5 lattice over it.
struct Node {
  int face, level;
  glm::dvec2 centre;
};

Node nodeAround(int face, int level, glm::dvec2 point) {
  const double size = std::ldexp(1.0, -level), cells = std::ldexp(1.0, level);
  const glm::dvec2 cell = glm::min(glm::floor(point * cells), glm::dvec2(cells - 1.0));
  return {face, level, (cell + 0.5) * size};
}

// Points of a face where the inverse is hardest: its corners (a pole for faces 0-3 and 8-11), its centre,
// astride a = 0 (x + y = 1) and random ones.
std::vector<glm::dvec2> probedPoints(std::mt19937_64& random) {
  std::vector<glm::dvec2> points = {
      {0, 0},      {1, 1}, {1, 0}, {0, 1}, {0.5, 0.5}, {0.3, 0.7}, {0.5 + 1e-9, 0.5}, {0.99999999, 0.99999999},
      {1e-8, 1e-8}};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 6; ++i) points.push_back({unit(random), unit(random)});
  return points;
}

struct Errors {
  double worst = 0.0;  // |gpu - double| / |double|
  int probes = 0;
};

// healpixOffset for each probe, run on the GPU and read back.
std::vector<glm::vec4> offsetsOnGpu(const std::vector<Probe>& probes) {
  ShaderLibrary library = test::pluginShaderLibrary();
  library.add("test/healpix_offset_probe.comp", kProbe);
  const ShaderProgram program(
      {{GL_COMPUTE_SHADER, "test/healpix_offset_probe.comp", library.expand("test/healpix_offset_probe.comp")}});
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  glNamedBufferStorage(buffers[0], GLsizeiptr(probes.size() * sizeof(Probe)), probes.data(), 0);
  glNamedBufferStorage(buffers[1], GLsizeiptr(probes.size() * sizeof(glm::vec4)), nullptr, 0);
  program.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  glDispatchCompute(GLuint(probes.size() + 63) / 64, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> offsets(probes.size());
  glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(offsets.size() * sizeof(glm::vec4)), offsets.data());
  glDeleteBuffers(2, buffers);
  return offsets;
}

TEST(HealpixOffset, MatchesTheDoubleInverseAtEveryLevel) {
  strata::test::headlessContext();
  std::mt19937_64 random(4);
  std::vector<Node> nodes;
  for (int face = 0; face < 12; ++face)
    for (const glm::dvec2& point : probedPoints(random))
      for (int level : {0, 2, 6, 10, 14, 18, 22, 26}) nodes.push_back(nodeAround(face, level, point));
  std::vector<Probe> probes;
  std::vector<glm::dvec3> expected;
  for (const Node& node : nodes) {
    const double size = std::ldexp(1.0, -node.level);
    const HealpixFrame frame = frameAt({node.face, node.centre.x, node.centre.y});
    const glm::dvec3 centre = unitVector({node.face, node.centre.x, node.centre.y});
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        const glm::dvec2 offset = (glm::dvec2(i, j) / 4.0 - 0.5) * size;  // exact in float: dyadic
        probes.push_back({frame, glm::vec4(glm::vec2(offset), 0.0f, 0.0f)});
        expected.push_back(unitVector({node.face, node.centre.x + offset.x, node.centre.y + offset.y}) - centre);
      }
  }

  const std::vector<glm::vec4> offsets = offsetsOnGpu(probes);
  Errors errors;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const double length = glm::length(expected[k]);
    if (length == 0.0) {
      EXPECT_EQ(glm::dvec3(offsets[k]), glm::dvec3(0.0)) << k;
      continue;
    }
    const double error = glm::length(glm::dvec3(offsets[k]) - expected[k]) / length;
    ++errors.probes;
    if (error > errors.worst) errors.worst = error;
    EXPECT_LT(error, kTolerance) << "face " << nodes[k / 25].face << ", level " << nodes[k / 25].level << ", centre ("
                                 << nodes[k / 25].centre.x << ", " << nodes[k / 25].centre.y << "), probe " << k % 25;
  }
  std::printf("%d probes: the worst error %.3g of the difference's length\n", errors.probes, errors.worst);
}

}  // namespace
}  // namespace strata::healpix
