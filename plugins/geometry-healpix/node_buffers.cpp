#include "node_buffers.hpp"

#include <numeric>
#include <vector>

#include "stitched_grid.hpp"

namespace strata::healpix {

NodeBuffers::NodeBuffers(int cells) : cells_(cells) {
  glCreateBuffers(kBufferCount, buffers_);
  const std::vector<std::uint32_t> indices = stitchedGridIndices(cells);
  glNamedBufferStorage(buffers_[kIndices], GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), 0);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayElementBuffer(vertexArray_, buffers_[kIndices]);
  glEnableVertexArrayAttrib(vertexArray_, 0);
  glVertexArrayAttribIFormat(vertexArray_, 0, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vertexArray_, 0, 0);
  glVertexArrayBindingDivisor(vertexArray_, 0, 1);
}

NodeBuffers::~NodeBuffers() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(kBufferCount, buffers_);
}

// Buffers with immutable storage are replaced, not resized: a node count this frame has not seen before
// makes them anew at twice the need.
void NodeBuffers::reserve(std::size_t nodes) {
  if (nodes <= capacity_) return;
  capacity_ = 2 * nodes;
  const GLuint replaced[] = {buffers_[kNodes], buffers_[kDraws], buffers_[kNodeNumbers], buffers_[kBoundary]};
  glDeleteBuffers(4, replaced);
  glCreateBuffers(1, &buffers_[kNodes]);
  glCreateBuffers(1, &buffers_[kDraws]);
  glCreateBuffers(1, &buffers_[kNodeNumbers]);
  glCreateBuffers(1, &buffers_[kBoundary]);
  glNamedBufferStorage(buffers_[kBoundary], GLsizeiptr(capacity_ * 4 * std::size_t(cells_) * sizeof(BoundaryVertex)),
                       nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(buffers_[kNodes], GLsizeiptr(capacity_ * sizeof(GpuNode)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(buffers_[kDraws], GLsizeiptr(capacity_ * sizeof(DrawElementsIndirectCommand)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  std::vector<std::uint32_t> numbers(capacity_);
  std::iota(numbers.begin(), numbers.end(), 0u);
  glNamedBufferStorage(buffers_[kNodeNumbers], GLsizeiptr(numbers.size() * sizeof(std::uint32_t)), numbers.data(), 0);
  glVertexArrayVertexBuffer(vertexArray_, 0, buffers_[kNodeNumbers], 0, sizeof(std::uint32_t));
}

void NodeBuffers::upload(const NodeBatch& batch) {
  nodes_ = batch.nodes.size();
  if (nodes_ == 0) return;
  reserve(nodes_);
  glNamedBufferSubData(buffers_[kNodes], 0, GLsizeiptr(nodes_ * sizeof(GpuNode)), batch.nodes.data());
  glNamedBufferSubData(buffers_[kDraws], 0, GLsizeiptr(nodes_ * sizeof(DrawElementsIndirectCommand)),
                       batch.draws.data());
  glNamedBufferSubData(buffers_[kBoundary], 0, GLsizeiptr(batch.boundary.size() * sizeof(BoundaryVertex)),
                       batch.boundary.data());
}

void NodeBuffers::draw() const {
  if (nodes_ == 0) return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers_[kNodes]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers_[kBoundary]);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers_[kDraws]);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, GLsizei(nodes_), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

}  // namespace strata::healpix
