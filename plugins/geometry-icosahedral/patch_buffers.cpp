#include "patch_buffers.hpp"

#include <algorithm>

namespace strata::icosahedral {

PatchBuffers::PatchBuffers(const SubdivisionTable& table, const EdgeWindings& windings)
    : verticesPerPatch_(std::size_t(table.vertexCount())) {
  glCreateBuffers(GLsizei(buffers_.size()), buffers_.data());
  const std::vector<std::uint32_t>& parents = table.parentPairs();
  glNamedBufferStorage(buffers_[kParents], GLsizeiptr(parents.size() * sizeof(std::uint32_t)), parents.data(), 0);
  const std::vector<std::uint32_t>& elements = windings.indices();
  glNamedBufferStorage(buffers_[kElements], GLsizeiptr(elements.size() * sizeof(std::uint32_t)), elements.data(), 0);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayElementBuffer(vertexArray_, buffers_[kElements]);
  // One attribute per buffer: position and spacing, normal, longitude and latitude.
  const std::array<GLint, 3> sizes{4, 4, 2};
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexArrayAttrib(vertexArray_, attribute);
    glVertexArrayAttribFormat(vertexArray_, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_, attribute, attribute);
  }
}

PatchBuffers::~PatchBuffers() {
  glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  glDeleteVertexArrays(1, &vertexArray_);
}

// Storage is immutable in GL 4.5, so growing makes new buffers; the per-frame ones are simply replaced.
void PatchBuffers::reserve(std::size_t patches) {
  if (patches <= capacity_) return;
  capacity_ = std::max(patches, capacity_ + capacity_ / 2);
  const std::array<std::pair<Buffer, std::size_t>, 5> sizes{{{kSeeds, 3 * sizeof(SeedCorner)},
                                                              {kDraws, sizeof(DrawElementsIndirectCommand)},
                                                              {kPositions, verticesPerPatch_ * sizeof(glm::vec4)},
                                                              {kNormals, verticesPerPatch_ * sizeof(glm::vec4)},
                                                              {kLonLats, verticesPerPatch_ * sizeof(glm::vec2)}}};
  for (const auto& [buffer, bytesPerPatch] : sizes) {
    glDeleteBuffers(1, &buffers_[buffer]);
    glCreateBuffers(1, &buffers_[buffer]);
    glNamedBufferStorage(buffers_[buffer], GLsizeiptr(capacity_ * bytesPerPatch), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glVertexArrayVertexBuffer(vertexArray_, 0, buffers_[kPositions], 0, sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vertexArray_, 1, buffers_[kNormals], 0, sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vertexArray_, 2, buffers_[kLonLats], 0, sizeof(glm::vec2));
}

void PatchBuffers::upload(const PatchBatch& batch) {
  patches_ = batch.draws.size();
  reserve(patches_);
  if (patches_ == 0) return;
  glNamedBufferSubData(buffers_[kSeeds], 0, GLsizeiptr(batch.seeds.size() * sizeof(SeedCorner)), batch.seeds.data());
  glNamedBufferSubData(buffers_[kDraws], 0, GLsizeiptr(batch.draws.size() * sizeof(DrawElementsIndirectCommand)),
                       batch.draws.data());
}

void PatchBuffers::subdivide() const {
  if (patches_ == 0) return;
  const std::array<Buffer, 5> bindings{kParents, kSeeds, kPositions, kNormals, kLonLats};  // as the shader binds them
  for (GLuint binding = 0; binding < bindings.size(); ++binding)
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffers_[bindings[binding]]);
  glDispatchCompute(GLuint(patches_), 1, 1);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
}

void PatchBuffers::draw() const {
  if (patches_ == 0) return;
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers_[kDraws]);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, GLsizei(patches_), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

std::vector<PatchBuffers::Vertex> PatchBuffers::readVertices() const {
  const std::size_t count = patches_ * verticesPerPatch_;
  std::vector<glm::vec4> positions(count), normals(count);
  std::vector<glm::vec2> lonlats(count);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffers_[kPositions], 0, GLsizeiptr(count * sizeof(glm::vec4)), positions.data());
  glGetNamedBufferSubData(buffers_[kNormals], 0, GLsizeiptr(count * sizeof(glm::vec4)), normals.data());
  glGetNamedBufferSubData(buffers_[kLonLats], 0, GLsizeiptr(count * sizeof(glm::vec2)), lonlats.data());
  std::vector<Vertex> vertices(count);
  for (std::size_t i = 0; i < count; ++i) vertices[i] = {positions[i], normals[i], lonlats[i]};
  return vertices;
}

}  // namespace strata::icosahedral
