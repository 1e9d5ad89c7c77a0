#include "outline_fan.hpp"

#include <algorithm>

#include "body_outline.hpp"

namespace strata::image {

OutlineFan::OutlineFan() {
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, BodyOutline::kMostPoints * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayVertexBuffer(vertexArray_, 0, buffer_, 0, sizeof(glm::vec4));
  glEnableVertexArrayAttrib(vertexArray_, 0);
  glVertexArrayAttribFormat(vertexArray_, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertexArray_, 0, 0);
}

OutlineFan::~OutlineFan() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(1, &buffer_);
}

void OutlineFan::draw(const std::vector<glm::vec4>& fan) const {
  const auto points = GLsizei(std::min<std::size_t>(fan.size(), BodyOutline::kMostPoints));
  glNamedBufferSubData(buffer_, 0, GLsizeiptr(points * sizeof(glm::vec4)), fan.data());
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLE_FAN, 0, points);
  glBindVertexArray(0);
}

}  // namespace strata::image
