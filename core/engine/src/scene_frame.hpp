#pragma once
#include <memory>
#include <vector>

#include <strata/gl/framebuffer.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/output.hpp>

namespace strata {

// The frame of a scene of several bodies: each body's frame, drawn with a transparent background, laid over
// space and the bodies behind it. Bodies are laid farthest first in the order of their power distance from the
// eye (|eye - centre|^2 - radius^2): two spheres apart are parted by their radical plane, and the one on the
// eye's side of it, of the lower power, hides the other wherever both show [Kooima 2008, §3.1: the bodies are
// drawn one after another]. Exact for bodies whose spheres of their highest ground do not meet.
class SceneFrame : public FrameOutput {
 public:
  explicit SceneFrame(ShaderLibrary& shaders);  // on the GL thread

  // Lays `farthestFirst` (RGBA8 frames of width x height, alpha the coverage) over black space.
  void compose(int width, int height, const std::vector<const Framebuffer*>& farthestFirst);

  const Framebuffer& frame() const override { return frame_; }
  void write(const std::filesystem::path& file) const override;

 private:
  ShaderProgram program_;
  FullscreenTriangle triangle_;
  Framebuffer frame_;
};

}  // namespace strata
