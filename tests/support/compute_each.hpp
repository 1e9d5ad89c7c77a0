#pragma once
#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <strata/gl/shader_program.hpp>

namespace strata::test {

// The GLSL of a compute shader for dispatchEach: the version line, `declarations` (includes, structs, uniforms),
// the storage buffers `arguments[]` of `argumentType` (binding 0) and `results[]` of `resultType` (binding 1),
// the uniform `count`, and a main() that runs `body` for each element `i` below it.
std::string eachElementShader(const std::string& declarations, const std::string& argumentType,
                              const std::string& resultType, const std::string& body);

// Runs `program`, a compute shader of local size 64 whose uniform `count` is the number of elements, which
// reads its arguments from the storage buffer at binding 0 and writes its results to the one at binding 1,
// over `count` elements; returns the `resultBytes` it wrote. On the headless context (headlessContext()).
std::vector<std::byte> dispatchEach(const ShaderProgram& program, std::span<const std::byte> arguments,
                                    std::size_t count, std::size_t resultBytes);

// The same with one Result per Argument.
template <class Result, class Argument>
std::vector<Result> computeEach(const ShaderProgram& program, const std::vector<Argument>& arguments) {
  const std::vector<std::byte> bytes =
      dispatchEach(program, std::as_bytes(std::span(arguments)), arguments.size(), arguments.size() * sizeof(Result));
  std::vector<Result> results(arguments.size());
  std::memcpy(results.data(), bytes.data(), bytes.size());
  return results;
}

}  // namespace strata::test
