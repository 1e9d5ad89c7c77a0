#pragma once
#include <cstdint>

#include <strata/gl.hpp>

#include "displaced_patch.hpp"
#include "patch_batch.hpp"

namespace strata::bdam {

// geometry.bdam's patches in graphics memory [Cignoni et al. 2003, §4.2: "static vertex arrays in graphics memory"]:
// one vertex buffer and one index buffer of fixed slots (the data's largest patch each, PatchSlots decides which
// patch a slot holds), each vertex as it is stored (two 16-bit barycentrics, a 32-bit displacement in cm); and each
// frame's patches and draws, drawn with one glMultiDrawElementsIndirect. A draw's baseInstance names its patch: an
// instanced attribute (divisor 1) reads it from a buffer of 0, 1, 2, ..., which GL 4.5 offsets by baseInstance.
class PatchBuffers {
 public:
  PatchBuffers(std::size_t slots, std::uint32_t mostVertices, std::uint32_t mostIndices);
  ~PatchBuffers();
  PatchBuffers(const PatchBuffers&) = delete;
  PatchBuffers& operator=(const PatchBuffers&) = delete;

  void upload(std::size_t slot, const DisplacedPatch& patch);
  // Uploads the frame's patches and draws them with the program in use (bdam_surface.vert).
  void draw(const PatchBatch& batch);
  std::uint64_t bytes() const;
  // Graphics memory a slot takes, for patches of up to so many vertices and indices.
  static std::uint64_t slotBytes(std::uint32_t mostVertices, std::uint32_t mostIndices);

 private:
  enum Buffer { kVertices, kIndices, kPatches, kDraws, kPatchNumbers, kBufferCount };
  void reserve(std::size_t patches);

  std::size_t slots_;
  std::uint32_t mostVertices_, mostIndices_;
  std::size_t capacity_ = 0;  // patches a frame
  GLuint buffers_[kBufferCount] = {};
  GLuint vertexArray_ = 0;
};

}  // namespace strata::bdam
