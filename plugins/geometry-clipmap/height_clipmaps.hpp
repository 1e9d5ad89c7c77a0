#pragma once
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <strata/camera.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

#include "height_windows.hpp"

namespace strata {
class Layer;
}

namespace strata::clipmap {

// The height clipmaps of spherical clipmaps [Clasen & Hege 2006, §3.1, §4.1 to §4.3]: each level's window
// (height_windows.hpp) in one layer of two array textures, the height (R32F, m) and its slopes east and north
// (RG16F, rise per metre along the ground, which half floats keep to a thousandth for shading), sampled from the
// height layer (clipmap_fill.comp), the slopes with them where the layer gives its own, else differenced from the
// heights (clipmap_slopes.comp). A frame samples only the texels its windows moved in, and every texel again once
// the layer's values have changed (Layer::revision): pages arriving in place of the coarser ones that stood in, a
// time series moving on. Level i lies in layer i mod the layers held: four more than the most levels a frame has
// asked for, so that a descent adding a level at a time does not sample every window again each time.
class HeightClipmaps {
 public:
  // `texels` a window across; `fill` samples the height layer, `slopes` (where the layer gives no slopes of its own)
  // differences the heights. On the GL thread.
  HeightClipmaps(int texels, ShaderProgram fill, std::optional<ShaderProgram> slopes);
  ~HeightClipmaps();
  HeightClipmaps(const HeightClipmaps&) = delete;
  HeightClipmaps& operator=(const HeightClipmaps&) = delete;

  // Brings the windows of levels `coarsest` to `finest` to `view`'s reference, sampling `layer` where they moved.
  // On the GL thread.
  void update(const View& view, double radius, const Layer& layer, int coarsest, int finest);
  // Binds the textures and sets the windows' uniforms (clipmap_heights.glsl) in `surface` (current), measured from
  // `reference`, for the levels the last update() brought there.
  void bind(ShaderProgram& surface, TextureUnits& units, glm::dvec2 reference) const;

 private:
  struct HeldWindow {
    int level = -1;  // none
    HeightWindow window;
  };
  void allocate(int layers);
  // Programs `program` (current) for `window` in layer `layer`, and dispatches it over `block`.
  void dispatch(ShaderProgram& program, int layer, const HeightWindow& window, const TexelBlock& block,
                glm::dvec2 reference) const;
  // Makes `program` current with the frame's uniforms.
  void useFor(ShaderProgram& program, const View& view, double radius) const;
  // The slopes of the blocks each level moved in (`moved`), and of the texels beside them, from the heights.
  void differenceSlopes(const std::vector<std::pair<int, std::vector<TexelBlock>>>& moved, const View& view,
                        double radius);

  int texels_;
  ShaderProgram fill_;
  std::optional<ShaderProgram> slopes_;
  GLuint textures_[2] = {};                // heights, slopes
  std::vector<HeldWindow> held_;           // per layer of the textures
  std::optional<std::uint64_t> revision_;  // the layer's when the held windows were sampled
  int coarsest_ = 0, finest_ = -1;
};

}  // namespace strata::clipmap
