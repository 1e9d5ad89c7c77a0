#pragma once
#include <array>

#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

#include "patch_batch.hpp"

namespace strata::icosahedral {

// The GPU side of the patches: the dependence table and the edge windings (uploaded once), the frame's
// seeds and draws, and the subdivided vertices, which the compute pass writes and the draw reads as
// vertex attributes with nothing copied (GL 4.5 forms of [Kooima 2008, §3.3.7, §3.4.1], which copies the
// vertices through a pixel buffer object and keeps the windings as eight element buffers).
class PatchBuffers {
 public:
  PatchBuffers(const SubdivisionTable& table, const EdgeWindings& windings);
  ~PatchBuffers();
  PatchBuffers(const PatchBuffers&) = delete;
  PatchBuffers& operator=(const PatchBuffers&) = delete;

  // Uploads the frame's seeds and draws, growing the buffers when there are more patches than before.
  void upload(const PatchBatch& batch);
  // Subdivides the uploaded patches with the program in use (subdivide_patches.comp).
  void subdivide() const;
  // Draws the subdivided patches with the program in use.
  void draw() const;

  // The subdivided vertices of the uploaded patches, read back from the GPU (which this waits for):
  // for tests and inspection.
  struct Vertex {
    glm::vec4 position;       // xyz: m on the sphere, relative to the eye; w: the patch's level
    glm::vec4 normal;         // xyz: planet-fixed unit normal; w: angle between the parents, rad
    glm::vec2 lonlat;         // rad from the frame's reference
    glm::vec2 drawnLonlat;    // rad from the frame's reference, as drawn (morphed)
    glm::vec4 drawn;          // xyz: m from the eye, displaced and morphed; w: the morph, 0 to 1
    glm::vec4 shadingNormal;  // xyz: planet-fixed normal of the displaced surface, as drawn; w: the detail scale
  };
  std::vector<Vertex> readVertices() const;

 private:
  enum Buffer {
    kParents,
    kElements,
    kSeeds,
    kDraws,
    kPositions,
    kNormals,
    kLonLats,
    kSurface,
    kShading,
    kDetails,
    kBufferCount
  };
  void reserve(std::size_t patches);

  std::size_t verticesPerPatch_;
  std::size_t capacity_ = 0;  // patches the per-frame buffers hold
  std::size_t patches_ = 0;   // patches uploaded this frame
  std::array<GLuint, kBufferCount> buffers_{};
  GLuint vertexArray_ = 0;
};

// Makes the compute pass (`program`, subdivide_patches.comp) current with its uniforms for the batch: the
// subdivision's depth, the reference, the body's radius, the height footprint, the split distances and
// the grazing cosine the tree's face-on distances use.
void useSubdivision(const ShaderProgram& program, const PatchBatch& batch, int depth, double radius);

}  // namespace strata::icosahedral
