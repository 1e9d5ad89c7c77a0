#pragma once
#include <strata/gl.hpp>

#include <vector>

#include "hemisphere_rings.hpp"

namespace strata::clipmap {

// The hemisphere on the GPU: its vertices and indices uploaded once, and the draw of a view's ranges of them
// (sector_culling.hpp) in one glMultiDrawElements.
class HemisphereBuffers {
 public:
  explicit HemisphereBuffers(const HemisphereRings& rings);
  ~HemisphereBuffers();
  HemisphereBuffers(const HemisphereBuffers&) = delete;
  HemisphereBuffers& operator=(const HemisphereBuffers&) = delete;

  // Draws `ranges` with the program in use (clipmap_surface.vert).
  void draw(const std::vector<IndexRange>& ranges) const;

 private:
  GLuint buffers_[2] = {};
  GLuint vertexArray_ = 0;
};

}  // namespace strata::clipmap
