#pragma once
#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

namespace strata::paging {

// Gives the pages of one-channel layers their value's slopes in their atlas slots (.b and .a beside value x
// coverage and coverage), right after each is uploaded: a compute pass over the slot
// (shaders/strata/page_value_slopes.comp), so that a sample's gradient comes from the four texels it filters
// (docs/paging.md, "Sampling in GLSL"). One program, compiled when the cache allocates. On the GL thread.
class ValueSlopesPages {
 public:
  ValueSlopesPages();
  // Fills the slopes of the page in `slot` of the RGBA32F array texture `atlas`.
  void compute(GLuint atlas, int slot) const;

 private:
  ShaderProgram program_;
};

}  // namespace strata::paging
