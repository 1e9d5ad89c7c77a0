#include "hemisphere_buffers.hpp"

#include <cstdint>

namespace strata::clipmap {

HemisphereBuffers::HemisphereBuffers(const HemisphereRings& rings) : levels_(rings.levels), caps_(rings.caps) {
  glCreateBuffers(2, buffers_);
  glNamedBufferStorage(buffers_[0], GLsizeiptr(rings.vertices.size() * sizeof(HemisphereVertex)), rings.vertices.data(),
                       0);
  glNamedBufferStorage(buffers_[1], GLsizeiptr(rings.indices.size() * sizeof(std::uint32_t)), rings.indices.data(), 0);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayElementBuffer(vertexArray_, buffers_[1]);
  glVertexArrayVertexBuffer(vertexArray_, 0, buffers_[0], 0, sizeof(HemisphereVertex));
  glEnableVertexArrayAttrib(vertexArray_, 0);
  glVertexArrayAttribFormat(vertexArray_, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertexArray_, 0, 0);
}

HemisphereBuffers::~HemisphereBuffers() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(2, buffers_);
}

void HemisphereBuffers::draw(const DrawnLevels& drawn) const {
  const IndexRange& coarsest = levels_[std::size_t(drawn.coarsest)];
  const IndexRange& finest = levels_[std::size_t(drawn.finest)];
  const IndexRange& cap = caps_[std::size_t(drawn.finest)];
  const GLsizei counts[] = {GLsizei(finest.first + finest.count - coarsest.first), GLsizei(cap.count)};
  const void* offsets[] = {reinterpret_cast<const void*>(std::uintptr_t(coarsest.first) * sizeof(std::uint32_t)),
                           reinterpret_cast<const void*>(std::uintptr_t(cap.first) * sizeof(std::uint32_t))};
  glBindVertexArray(vertexArray_);
  glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets, 2);
  glBindVertexArray(0);
}

}  // namespace strata::clipmap
