// Reversed depth with an infinite far plane (core/foundation/src/view.cpp) keeps surfaces apart at every scale a
// view spans: a 1 cm step 2 m below the eye, and surfaces 1 km apart 20,000 km away. Two planes facing the
// eye are drawn through the view's own projection into the DEPTH32F target the generators use, with the
// engine's GL_GREATER test and [0, 1] clip depth, in both orders: the nearer must win each time.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <strata/camera.hpp>
#include <strata/gl/framebuffer.hpp>
#include <strata/gl/shader_program.hpp>

#include "rendering.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 16;

// A plane facing the eye at eye-space depth -distance, wide enough to cover the view: eye-relative floats,
// as every mesh reaches the GPU.
const char* kVertex = R"(#version 450 core
uniform mat4 projection;
uniform float distance;
void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 2.0;
  gl_Position = projection * vec4(corner * distance, -distance, 1.0);
}
)";
const char* kFragment = R"(#version 450 core
uniform float shade;
out vec4 colour;
void main() { colour = vec4(shade, 0.0, 0.0, 1.0); }
)";

// The red of the centre pixel after drawing planes at `first` and then `second` metres, shaded 0.25 and 0.75.
float drawnShade(const View& view, double first, double second) {
  headlessContext();
  const Framebuffer target(kSize, kSize, {GL_RGBA8}, GL_DEPTH_COMPONENT32F);
  const ShaderProgram program(
      {{GL_VERTEX_SHADER, "plane.vert", kVertex}, {GL_FRAGMENT_SHADER, "plane.frag", kFragment}});
  GLuint vertexArray = 0;
  glCreateVertexArrays(1, &vertexArray);
  target.bind();
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // as the engine renders
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  const float clearColour[4] = {0, 0, 0, 0}, farDepth = 0.0f;
  glClearBufferfv(GL_COLOR, 0, clearColour);
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
  program.use();
  glUniformMatrix4fv(program.location("projection"), 1, GL_FALSE, &view.projection[0][0]);
  glBindVertexArray(vertexArray);
  for (auto [distance, shade] : {std::pair{first, 0.25f}, {second, 0.75f}}) {
    program.set("distance", float(distance));
    program.set("shade", shade);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  std::vector<float> pixel(4);
  glReadPixels(kSize / 2, kSize / 2, 1, 1, GL_RGBA, GL_FLOAT, pixel.data());
  glDisable(GL_DEPTH_TEST);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDeleteVertexArrays(1, &vertexArray);
  return pixel[0];
}

// 0.25 and 0.75 are 64 and 191 of 255 in RGBA8: a tolerance of 0.01 tells them apart with room to spare.
void expectNearerWins(const View& view, double nearer, double farther) {
  EXPECT_NEAR(drawnShade(view, farther, nearer), 0.75f, 0.01f) << "the nearer plane, drawn second, must pass";
  EXPECT_NEAR(drawnShade(view, nearer, farther), 0.25f, 0.01f) << "the farther plane, drawn second, must fail";
}

TEST(ReversedDepth, SeparatesACentimetreTwoMetresBelowTheEye) {
  const View view = makeView(Body{}, Camera{.lon = 137.4, .lat = -4.6, .altitude = 2.0}, kSize, kSize);
  expectNearerWins(view, 1.99, 2.0);
}

TEST(ReversedDepth, SeparatesAKilometreTwentyThousandKilometresAway) {
  const View view = makeView(Body{}, Camera{.altitude = 2.0e7}, kSize, kSize);
  expectNearerWins(view, 2.0e7, 2.0e7 + 1.0e3);
}

}  // namespace
}  // namespace strata::test
