#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

#include "cross_section.hpp"
#include "sampling_camera.hpp"

namespace strata::pgm {

// The unit ray of grid point (column, row) of a grid of `size` points, in sampling space: the point
// column/(W - 1), row/(H - 1) of the frustum's near plane, so that the outer rows and columns lie on its
// edges, where the rays it was fitted to lie. The double twin of pgm_cast.comp's gridRay.
glm::dvec3 gridRay(const SamplingCamera& camera, glm::ivec2 size, int column, int row);

// Makes the cast pass (`program`, plugins/geometry-pgm/pgm_cast.comp) current with its uniforms: the grid's
// size, the sampling frustum, the rotation from sampling space to the east-north-up frame at the point below
// the eye (strata/camera.hpp's planetToLocal), and the cross section's constants. Every double becomes a
// float here, and nothing planet-sized but the primary radius goes up [Mahsman 2010, §3.6.5].
void useCast(const ShaderProgram& program, const SamplingCamera& camera, const CrossSection& view,
             const glm::dmat3& samplingToLocal, glm::ivec2 size);

// The pass's two grid-sized buffers, row by row [Mahsman 2010, §3.6.1], for grids of up to `capacity` points.
class CastBuffers {
 public:
  explicit CastBuffers(glm::ivec2 capacity);
  ~CastBuffers();
  CastBuffers(const CastBuffers&) = delete;
  CastBuffers& operator=(const CastBuffers&) = delete;

  // Casts the rays of a grid of `size` points with the program in use (pgm_cast.comp, whose gridSize it must be).
  void cast(glm::ivec2 size) const;

  // What the pass wrote for each grid point of a grid of the capacity, read back from the GPU (which this waits
  // for): for tests.
  struct Point {
    glm::vec4 normal;    // xyz: the unit sphere normal in the local frame; w: 1 for a hit, 0 for a miss
    glm::vec4 position;  // xyz: from the eye in the local frame; zero for a miss
  };
  std::vector<Point> read() const;

  // Binds the two buffers to shader storage bindings `first` and `first + 1`, for the passes that read them.
  void bind(GLuint first) const;

 private:
  glm::ivec2 capacity_;
  std::array<GLuint, 2> buffers_{};  // normals, positions: bindings 0 and 1
};

}  // namespace strata::pgm
