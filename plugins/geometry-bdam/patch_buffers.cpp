#include "patch_buffers.hpp"

#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::bdam {

static_assert(sizeof(DisplacedVertex) == 8, "vertices are uploaded as they are held");

PatchBuffers::PatchBuffers(std::size_t slots, std::uint32_t mostVertices, std::uint32_t mostIndices)
    : slots_(slots), mostVertices_(mostVertices), mostIndices_(mostIndices) {
  glCreateBuffers(kBufferCount, buffers_);
  glNamedBufferStorage(buffers_[kVertices], GLsizeiptr(slots * mostVertices * sizeof(DisplacedVertex)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(buffers_[kIndices], GLsizeiptr(slots * mostIndices * sizeof(std::uint32_t)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayElementBuffer(vertexArray_, buffers_[kIndices]);
  glVertexArrayVertexBuffer(vertexArray_, 0, buffers_[kVertices], 0, sizeof(DisplacedVertex));
  glEnableVertexArrayAttrib(vertexArray_, 0);  // b1, b2
  glVertexArrayAttribIFormat(vertexArray_, 0, 2, GL_UNSIGNED_SHORT, 0);
  glVertexArrayAttribBinding(vertexArray_, 0, 0);
  glEnableVertexArrayAttrib(vertexArray_, 1);  // centimetres
  glVertexArrayAttribIFormat(vertexArray_, 1, 1, GL_INT, 4);
  glVertexArrayAttribBinding(vertexArray_, 1, 0);
  glEnableVertexArrayAttrib(vertexArray_, 2);  // the patch's number
  glVertexArrayAttribIFormat(vertexArray_, 2, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vertexArray_, 2, 1);
  glVertexArrayBindingDivisor(vertexArray_, 1, 1);
}

PatchBuffers::~PatchBuffers() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(kBufferCount, buffers_);
}

void PatchBuffers::upload(std::size_t slot, const DisplacedPatch& patch) {
  if (slot >= slots_ || patch.vertices.size() > mostVertices_ || patch.indices.size() > mostIndices_)
    throw std::logic_error("a patch of " + std::to_string(patch.vertices.size()) + " vertices for slot " +
                           std::to_string(slot));
  glNamedBufferSubData(buffers_[kVertices], GLintptr(slot * mostVertices_ * sizeof(DisplacedVertex)),
                       GLsizeiptr(patch.vertices.size() * sizeof(DisplacedVertex)), patch.vertices.data());
  glNamedBufferSubData(buffers_[kIndices], GLintptr(slot * mostIndices_ * sizeof(std::uint32_t)),
                       GLsizeiptr(patch.indices.size() * sizeof(std::uint32_t)), patch.indices.data());
}

// Buffers with immutable storage are replaced, not resized: more patches than before makes them anew at twice.
void PatchBuffers::reserve(std::size_t patches) {
  if (patches <= capacity_) return;
  capacity_ = 2 * patches;
  const GLuint replaced[] = {buffers_[kPatches], buffers_[kDraws], buffers_[kPatchNumbers]};
  glDeleteBuffers(3, replaced);
  for (Buffer b : {kPatches, kDraws, kPatchNumbers}) glCreateBuffers(1, &buffers_[b]);
  glNamedBufferStorage(buffers_[kPatches], GLsizeiptr(capacity_ * sizeof(GpuPatch)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(buffers_[kDraws], GLsizeiptr(capacity_ * sizeof(DrawElementsIndirectCommand)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  std::vector<std::uint32_t> numbers(capacity_);
  std::iota(numbers.begin(), numbers.end(), 0u);
  glNamedBufferStorage(buffers_[kPatchNumbers], GLsizeiptr(numbers.size() * sizeof(std::uint32_t)), numbers.data(), 0);
  glVertexArrayVertexBuffer(vertexArray_, 1, buffers_[kPatchNumbers], 0, sizeof(std::uint32_t));
}

void PatchBuffers::draw(const PatchBatch& batch) {
  if (batch.patches.empty()) return;
  reserve(batch.patches.size());
  glNamedBufferSubData(buffers_[kPatches], 0, GLsizeiptr(batch.patches.size() * sizeof(GpuPatch)),
                       batch.patches.data());
  glNamedBufferSubData(buffers_[kDraws], 0, GLsizeiptr(batch.draws.size() * sizeof(DrawElementsIndirectCommand)),
                       batch.draws.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers_[kPatches]);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers_[kDraws]);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, GLsizei(batch.draws.size()), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

std::uint64_t PatchBuffers::slotBytes(std::uint32_t mostVertices, std::uint32_t mostIndices) {
  return mostVertices * sizeof(DisplacedVertex) + mostIndices * sizeof(std::uint32_t);
}

std::uint64_t PatchBuffers::bytes() const {
  return slots_ * slotBytes(mostVertices_, mostIndices_) +
         capacity_ * (sizeof(GpuPatch) + sizeof(DrawElementsIndirectCommand) + sizeof(std::uint32_t));
}

}  // namespace strata::bdam
