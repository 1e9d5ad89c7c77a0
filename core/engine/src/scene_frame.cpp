#include "scene_frame.hpp"

#include <strata/gl.hpp>

namespace strata {

SceneFrame::SceneFrame(ShaderLibrary& shaders)
    : program_({{GL_VERTEX_SHADER, "strata/fullscreen.vert", shaders.expand("strata/fullscreen.vert")},
                {GL_FRAGMENT_SHADER, "strata/frame_over.frag", shaders.expand("strata/frame_over.frag")}}) {}

// Each frame is blended over what lies behind by its coverage, premultiplied (FrameState::transparentBackground), in
// the display's encoding: only pixels across a body's edge blend, where the difference from blending in linear
// light is a share of one pixel's step; light beyond a body's edge (its air) is added. The frame's own alpha stays
// 1: it is opaque, space included.
void SceneFrame::compose(int width, int height, const std::vector<const Framebuffer*>& farthestFirst) {
  if (frame_.width() != width || frame_.height() != height) frame_ = Framebuffer(width, height, {GL_RGBA8});
  frame_.bind();
  glDisable(GL_DEPTH_TEST);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);  // space: black, as output.image's background
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  program_.use();
  for (const Framebuffer* body : farthestFirst) {
    TextureUnits units;
    units.bind(program_, "bodyFrame", body->color(0).id());
    triangle_.draw();
  }
  glDisable(GL_BLEND);
}

void SceneFrame::write(const std::filesystem::path& file) const {
  writeImage(file, frame_.width(), frame_.height(), readPixels(frame_));
}

}  // namespace strata
