#include "compute_each.hpp"

#include <array>

#include <strata/gl.hpp>

namespace strata::test {

std::vector<std::byte> dispatchEach(const ShaderProgram& program, std::span<const std::byte> arguments,
                                    std::size_t count, std::size_t resultBytes) {
  std::array<GLuint, 2> buffers{};
  glCreateBuffers(2, buffers.data());
  glNamedBufferStorage(buffers[0], GLsizeiptr(arguments.size()), arguments.data(), 0);
  glNamedBufferStorage(buffers[1], GLsizeiptr(resultBytes), nullptr, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  program.use();
  program.set("count", unsigned(count));
  glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::byte> results(resultBytes);
  glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(resultBytes), results.data());
  glDeleteBuffers(2, buffers.data());
  return results;
}

}  // namespace strata::test
