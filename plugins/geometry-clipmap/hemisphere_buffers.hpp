#pragma once
#include <strata/gl.hpp>

#include "drawn_levels.hpp"
#include "hemisphere_rings.hpp"

namespace strata::clipmap {

// The hemisphere on the GPU: its vertices and indices uploaded once, and the draw of a view's levels and fill cap
// (one range of indices for the levels, which lie coarsest first, and one for the cap).
class HemisphereBuffers {
 public:
  explicit HemisphereBuffers(const HemisphereRings& rings);
  ~HemisphereBuffers();
  HemisphereBuffers(const HemisphereBuffers&) = delete;
  HemisphereBuffers& operator=(const HemisphereBuffers&) = delete;

  // Draws `drawn` with the program in use (clipmap_surface.vert).
  void draw(const DrawnLevels& drawn) const;

 private:
  std::vector<IndexRange> levels_, caps_;
  GLuint buffers_[2] = {};
  GLuint vertexArray_ = 0;
};

}  // namespace strata::clipmap
