#include "grid_mesh.hpp"

#include <cmath>
#include <vector>

#include <strata/camera.hpp>

namespace strata::pgm {
namespace {

constexpr GLuint kGroupSide = 8;  // the local size of pgm_displace.comp

// Six indices per cell: two triangles over the diagonal from its lower left corner to its upper right.
std::vector<GLuint> triangleIndices(glm::ivec2 size) {
  std::vector<GLuint> indices;
  indices.reserve(6 * std::size_t(size.x - 1) * std::size_t(size.y - 1));
  for (int row = 0; row + 1 < size.y; ++row) {
    for (int column = 0; column + 1 < size.x; ++column) {
      const GLuint lowerLeft = GLuint(row * size.x + column), upperLeft = lowerLeft + GLuint(size.x);
      indices.insert(indices.end(), {lowerLeft, lowerLeft + 1, upperLeft + 1, lowerLeft, upperLeft + 1, upperLeft});
    }
  }
  return indices;
}

void dispatchOver(glm::ivec2 size) {
  glDispatchCompute((GLuint(size.x) + kGroupSide - 1) / kGroupSide, (GLuint(size.y) + kGroupSide - 1) / kGroupSide, 1);
}

glm::vec2 sinCosOfLatitude(const View& view) {
  return {float(std::sin(view.reference.y)), float(std::cos(view.reference.y))};
}

}  // namespace

GridMesh::GridMesh(glm::ivec2 capacity) {
  glCreateBuffers(1, &vertices_);
  glNamedBufferStorage(vertices_, GLsizeiptr(capacity.x) * capacity.y * GLsizeiptr(sizeof(Vertex)), nullptr, 0);
  glCreateVertexArrays(1, &vertexArray_);
}

GridMesh::~GridMesh() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(1, &vertices_);
  for (const auto& [size, buffer] : indices_) glDeleteBuffers(1, &buffer);
}

GLuint GridMesh::indicesOf(glm::ivec2 size) {
  GLuint& buffer = indices_[{size.x, size.y}];
  if (buffer == 0) {
    const std::vector<GLuint> indices = triangleIndices(size);
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(), 0);
  }
  return buffer;
}

void GridMesh::displace(const CastBuffers& cast, glm::ivec2 size) const {
  cast.bind(0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, vertices_);
  dispatchOver(size);
}

void GridMesh::draw(glm::ivec2 size) {
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertices_);
  glVertexArrayElementBuffer(vertexArray_, indicesOf(size));
  glBindVertexArray(vertexArray_);
  glDrawElements(GL_TRIANGLES, GLsizei(3 * triangles(size)), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void useDisplacement(const ShaderProgram& program, glm::ivec2 size, const View& view, double bodyRadius,
                     double primaryRadius) {
  program.use();
  program.set("gridSize", size);
  program.set("localToPlanet", glm::mat3(glm::transpose(planetToLocal(view.reference))));
  program.set("referenceLatitude", sinCosOfLatitude(view));
  program.set("referenceLonlat", glm::vec2(view.reference));
  program.set("radius", float(bodyRadius));
  program.set("primaryOffset", float(bodyRadius - primaryRadius));
}

void useGridSurface(const ShaderProgram& program, const View& view) {
  const glm::dmat3 localToPlanet = glm::transpose(planetToLocal(view.reference));
  program.use();
  program.set("localToEye", glm::mat3(view.planetToEye * localToPlanet));
  program.set("projection", view.projection);
  program.set("referenceLatitude", sinCosOfLatitude(view));
}

}  // namespace strata::pgm
