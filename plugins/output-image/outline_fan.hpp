#pragma once
#include <vector>

#include <glm/vec4.hpp>
#include <strata/gl.hpp>

namespace strata::image {

// Draws a body's outline (body_outline.hpp) as a triangle fan with the bound program (outline.vert): the points,
// at most BodyOutline::kMostPoints, are copied to a buffer of its own each frame.
class OutlineFan {
 public:
  OutlineFan();
  ~OutlineFan();
  OutlineFan(const OutlineFan&) = delete;
  OutlineFan& operator=(const OutlineFan&) = delete;

  void draw(const std::vector<glm::vec4>& fan) const;

 private:
  GLuint buffer_ = 0;
  GLuint vertexArray_ = 0;
};

}  // namespace strata::image
