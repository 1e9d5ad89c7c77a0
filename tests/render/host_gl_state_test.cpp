// Engine::render on a host's context (docs/sdk/embedding.md): the host's framebuffer bindings, viewport and
// clip control are as they were when it returns, so that the host's own drawing after it (a UI over the
// frame) lands where the host meant.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include <strata/gl.hpp>
#include <strata/gl/framebuffer.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

// What a host set before the frame: its own framebuffer for drawing, another for reading, a viewport and
// OpenGL's default clip control.
struct HostBindings {
  GLint draw = 0, read = 0, clipOrigin = 0, clipDepth = 0;
  std::array<GLint, 4> viewport{};
  bool operator==(const HostBindings&) const = default;
};

HostBindings currentBindings() {
  HostBindings bindings;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bindings.draw);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bindings.read);
  glGetIntegerv(GL_VIEWPORT, bindings.viewport.data());
  glGetIntegerv(GL_CLIP_ORIGIN, &bindings.clipOrigin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &bindings.clipDepth);
  return bindings;
}

TEST(HostGlState, RenderLeavesTheHostsFramebuffersViewportAndClipControl) {
  TemporaryDirectory directory;
  std::unique_ptr<Engine> engine = makeEngine();
  engine->load(directory.write("sphere.yaml",
                               "strata: 1\nnodes:\n"
                               "  colours: {type: source.procedural, kind: color}\n"
                               "  globe: {type: geometry.icosahedral}\n"
                               "  frame: {type: output.image, geometry: globe, surface: [colours]}\n"));
  const Framebuffer drawTarget(64, 48, {GL_RGBA8}), readTarget(32, 32, {GL_RGBA8});
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, drawTarget.id());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readTarget.id());
  glViewport(3, 5, 40, 30);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  const HostBindings before = currentBindings();
  engine->render(96, 64);
  EXPECT_EQ(currentBindings(), before);
  EXPECT_EQ(before.clipDepth, GL_NEGATIVE_ONE_TO_ONE) << "the engine draws with [0, 1] depth, and put it back";
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace strata::test
