#include "compute_each.hpp"

#include <array>

#include <strata/gl.hpp>

namespace strata::test {

std::string eachElementShader(const std::string& declarations, const std::string& argumentType,
                              const std::string& resultType, const std::string& body) {
  return "#version 450 core\n" + declarations +
         "\nlayout(local_size_x = 64) in;\n"
         "layout(std430, binding = 0) readonly buffer Arguments { " +
         argumentType +
         " arguments[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Results { " +
         resultType +
         " results[]; };\n"
         "uniform uint count;\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  if (i >= count) return;\n" +
         body + "}\n";
}

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
