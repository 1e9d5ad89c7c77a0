#pragma once
#include <cstdint>
#include <map>
#include <utility>

#include <glm/glm.hpp>

#include <strata/camera.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

#include "pgm_cast.hpp"

namespace strata::pgm {

// The displaced grid of projective grid mapping [Mahsman 2010, §3.7.2] on the GPU: one vertex per grid
// point, made by plugins/geometry-pgm/pgm_displace.comp from the cast pass's buffers, and two triangles per
// grid cell, drawn by pgm_grid.vert. Every ray has a point (one that misses lies on the horizon,
// pgm_cast.comp), so the triangles are the same every frame: the diagonal from each cell's lower left to
// its upper right corner, counter-clockwise as rows and columns run in the sampling camera's image, and so
// as seen from the eye, whatever the camera's rotation. A frame's grid may be any size up to the capacity
// (grid_detail.hpp): the vertices of a grid of size (c, r) take the first c x r places, and each size drawn
// keeps its own triangles.
class GridMesh {
 public:
  explicit GridMesh(glm::ivec2 capacity);
  ~GridMesh();
  GridMesh(const GridMesh&) = delete;
  GridMesh& operator=(const GridMesh&) = delete;

  // With pgm_displace.comp in use (useDisplacement with `size`): the vertices from the cast pass's buffers.
  void displace(const CastBuffers& cast, glm::ivec2 size) const;
  // With pgm_grid.vert in use: draws the triangles of a grid of `size`.
  void draw(glm::ivec2 size);

  static std::uint64_t triangles(glm::ivec2 size) { return 2 * std::uint64_t(size.x - 1) * std::uint64_t(size.y - 1); }

  // What pgm_displace.comp writes for each grid point (pgm_grid_vertex.glsl).
  struct Vertex {
    glm::vec4 point;    // xyz: displaced, m from the eye, local frame; w: height above the body's radius
    glm::vec4 normal;   // xyz: the sphere normal, local frame; w: 1 for a hit
    glm::vec4 shading;  // xyz: the displaced surface's normal, planet-fixed
  };

 private:
  GLuint indicesOf(glm::ivec2 size);

  GLuint vertices_ = 0;
  std::map<std::pair<int, int>, GLuint> indices_;  // by the grid's columns and rows, made when first drawn
  GLuint vertexArray_ = 0;  // empty: the vertex shader pulls its vertices; it holds the index buffer drawn
};

// The displacement pass's uniforms for a view (pgm_displace.comp): the local frame at View::reference, the
// body's radius and the offset from the primary sphere down to it, R - r_p, formed in double.
void useDisplacement(const ShaderProgram& program, glm::ivec2 size, const View& view, double bodyRadius,
                     double primaryRadius);

// The rasterisation's uniforms (pgm_grid.vert, pgm_surface_buffer.frag).
void useGridSurface(const ShaderProgram& program, const View& view);

}  // namespace strata::pgm
