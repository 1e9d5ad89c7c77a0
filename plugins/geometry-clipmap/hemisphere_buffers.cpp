#include "hemisphere_buffers.hpp"

#include <cstdint>

namespace strata::clipmap {

HemisphereBuffers::HemisphereBuffers(const HemisphereRings& rings) {
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

void HemisphereBuffers::draw(const std::vector<IndexRange>& ranges) const {
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  for (const IndexRange& range : ranges) {
    counts.push_back(GLsizei(range.count));
    offsets.push_back(reinterpret_cast<const void*>(std::uintptr_t(range.first) * sizeof(std::uint32_t)));
  }
  glBindVertexArray(vertexArray_);
  glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(ranges.size()));
  glBindVertexArray(0);
}

}  // namespace strata::clipmap
