#include "patch_buffers.hpp"

#include <algorithm>
#include <cmath>

#include "patch_shell.hpp"

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
  // One attribute per buffer (icosahedral.vert): the drawn point, the drawn longitude and latitude (zw of
  // theirs), the shading normal.
  const std::array<GLint, 3> sizes{4, 2, 4};
  const std::array<GLuint, 3> offsets{0, 2 * sizeof(float), 0};
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexArrayAttrib(vertexArray_, attribute);
    glVertexArrayAttribFormat(vertexArray_, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, offsets[attribute]);
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
  const std::size_t vertexVector = verticesPerPatch_ * sizeof(glm::vec4);
  const std::array<std::pair<Buffer, std::size_t>, 8> sizes{{{kSeeds, 3 * sizeof(SeedCorner)},
                                                             {kDetails, DetailField::kPatchValues * sizeof(float)},
                                                             {kDraws, sizeof(DrawElementsIndirectCommand)},
                                                             {kPositions, vertexVector},
                                                             {kNormals, vertexVector},
                                                             {kLonLats, vertexVector},
                                                             {kSurface, vertexVector},
                                                             {kShading, vertexVector}}};
  for (const auto& [buffer, bytesPerPatch] : sizes) {
    glDeleteBuffers(1, &buffers_[buffer]);
    glCreateBuffers(1, &buffers_[buffer]);
    glNamedBufferStorage(buffers_[buffer], GLsizeiptr(capacity_ * bytesPerPatch), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  const std::array<Buffer, 3> attributes{kSurface, kLonLats, kShading};  // as the constructor's
  for (GLuint binding = 0; binding < attributes.size(); ++binding)
    glVertexArrayVertexBuffer(vertexArray_, binding, buffers_[attributes[binding]], 0, sizeof(glm::vec4));
}

void PatchBuffers::upload(const PatchBatch& batch) {
  patches_ = batch.draws.size();
  reserve(patches_);
  if (patches_ == 0) return;
  glNamedBufferSubData(buffers_[kSeeds], 0, GLsizeiptr(batch.seeds.size() * sizeof(SeedCorner)), batch.seeds.data());
  glNamedBufferSubData(buffers_[kDetails], 0, GLsizeiptr(batch.details.size() * sizeof(float)), batch.details.data());
  glNamedBufferSubData(buffers_[kDraws], 0, GLsizeiptr(batch.draws.size() * sizeof(DrawElementsIndirectCommand)),
                       batch.draws.data());
}

void PatchBuffers::subdivide() const {
  if (patches_ == 0) return;
  const std::array<Buffer, 8> bindings{kParents, kSeeds,   kPositions, kNormals,
                                       kLonLats, kSurface, kShading,   kDetails};  // as the shader binds them
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
  const std::array<Buffer, 5> read{kPositions, kNormals, kLonLats, kSurface, kShading};
  std::array<std::vector<glm::vec4>, 5> values;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  for (std::size_t b = 0; b < read.size(); ++b) {
    values[b].resize(count);
    glGetNamedBufferSubData(buffers_[read[b]], 0, GLsizeiptr(count * sizeof(glm::vec4)), values[b].data());
  }
  std::vector<Vertex> vertices(count);
  for (std::size_t i = 0; i < count; ++i)
    vertices[i] = {values[0][i], values[1][i], glm::vec2(values[2][i]), glm::vec2(values[2][i].z, values[2][i].w),
                   values[3][i], values[4][i]};
  return vertices;
}

void useSubdivision(const ShaderProgram& program, const PatchBatch& batch, int depth, double radius) {
  program.use();
  program.set("depth", depth);
  program.set("referenceLatitude", glm::vec2(std::sin(batch.reference.lat), std::cos(batch.reference.lat)));
  program.set("referenceLonlat", glm::vec2(batch.reference.lon, batch.reference.lat));
  program.set("radius", float(radius));
  program.set("footprintPerMetre", float(batch.footprintPerMetre));
  program.set("splitDistanceUnit", float(batch.splitDistanceUnit));
  program.set("latticeLevel", DetailField::kLevel);
  program.set("patchValues", DetailField::kPatchValues);
  program.set("grazingCosine", float(kGrazingCosine));
  program.set("onTerrain", int(batch.onTerrain));
}

}  // namespace strata::icosahedral
