#pragma once
#include <set>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <strata/gl.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// A linked GLSL 4.50 program. A compile or link failure throws std::runtime_error quoting the driver's log
// and the offending source lines, named by the stage's origin (e.g. "geometry-icosahedral/icosahedral.vert").
class ShaderProgram {
 public:
  struct Stage {
    GLenum type;         // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string origin;  // for messages
    std::string source;  // complete source, starting with #version
  };

  ShaderProgram() = default;
  explicit ShaderProgram(const std::vector<Stage>& stages);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  void use() const;
  GLint location(const std::string& uniform) const;  // -1 when the uniform is unused

  void set(const std::string& uniform, int value) const;
  void set(const std::string& uniform, unsigned value) const;
  void set(const std::string& uniform, const glm::ivec2& value) const;
  void set(const std::string& uniform, const glm::ivec3& value) const;
  void set(const std::string& uniform, float value) const;
  void set(const std::string& uniform, const glm::vec2& value) const;
  void set(const std::string& uniform, const glm::vec3& value) const;
  void set(const std::string& uniform, const glm::vec4& value) const;
  void set(const std::string& uniform, const glm::mat3& value) const;
  void set(const std::string& uniform, const glm::mat4& value) const;

 private:
  GLuint program_ = 0;
};

// Hands out texture units while a program's inputs are bound.
class TextureUnits {
 public:
  TextureUnits();  // on the GL thread
  // Binds `texture` to the next free unit and points the sampler uniform at it. A sampler already bound
  // keeps its unit: textures several layers share (the page cache's) take one unit, not one per layer.
  void bind(ShaderProgram& program, const std::string& sampler, GLuint texture);
  int used() const { return next_; }

 private:
  int available_ = 0;
  int next_ = 0;
  std::set<std::string> bound_;
};

}  // namespace strata
STRATA_EXPORTS_END
