#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include <strata/gl/shader_program.hpp>

namespace strata {
namespace {

const char* stageName(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    default: return "shader";
  }
}

// The source with line numbers, so a driver log's "0:42(7)" can be read against it.
std::string numbered(const std::string& source) {
  std::istringstream lines(source);
  std::ostringstream out;
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) out << number << ": " << line << '\n';
  return out.str();
}

GLuint compile(const ShaderProgram::Stage& stage) {
  GLuint shader = glCreateShader(stage.type);
  const char* text = stage.source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  glDeleteShader(shader);
  throw std::runtime_error(std::string("the ") + stageName(stage.type) + " shader '" + stage.origin +
                           "' failed to compile:\n" + log.c_str() + "\nsource:\n" + numbered(stage.source));
}

}  // namespace

ShaderProgram::ShaderProgram(const std::vector<Stage>& stages) {
  std::vector<GLuint> shaders;
  try {
    for (const Stage& stage : stages) shaders.push_back(compile(stage));
  } catch (...) {
    for (GLuint shader : shaders) glDeleteShader(shader);
    throw;
  }
  program_ = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program_, shader);
  glLinkProgram(program_);
  for (GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok) return;
  GLint length = 0;
  glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(program_, length, nullptr, log.data());
  glDeleteProgram(program_);
  program_ = 0;
  std::string origins;
  for (const Stage& stage : stages) origins += (origins.empty() ? "" : ", ") + stage.origin;
  throw std::runtime_error("the program of " + origins + " failed to link:\n" + log.c_str());
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : program_(other.program_) { other.program_ = 0; }

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  std::swap(program_, other.program_);
  return *this;
}

void ShaderProgram::use() const { glUseProgram(program_); }

GLint ShaderProgram::location(const std::string& uniform) const {
  return glGetUniformLocation(program_, uniform.c_str());
}

void ShaderProgram::set(const std::string& u, int v) const { glProgramUniform1i(program_, location(u), v); }
void ShaderProgram::set(const std::string& u, unsigned v) const { glProgramUniform1ui(program_, location(u), v); }
void ShaderProgram::set(const std::string& u, const glm::ivec2& v) const {
  glProgramUniform2iv(program_, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::ivec3& v) const {
  glProgramUniform3iv(program_, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, float v) const { glProgramUniform1f(program_, location(u), v); }
void ShaderProgram::set(const std::string& u, const glm::vec2& v) const {
  glProgramUniform2fv(program_, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec3& v) const {
  glProgramUniform3fv(program_, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec4& v) const {
  glProgramUniform4fv(program_, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat3& v) const {
  glProgramUniformMatrix3fv(program_, location(u), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(program_, location(u), 1, GL_FALSE, glm::value_ptr(v));
}

TextureUnits::TextureUnits() { glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &available_); }

void TextureUnits::bind(ShaderProgram& program, const std::string& sampler, GLuint texture) {
  if (!bound_.insert(sampler).second) return;
  if (next_ >= available_)
    throw std::runtime_error("more textures than the " + std::to_string(available_) +
                             " texture units this GPU has; the page-cache atlas lifts this limit");
  glBindTextureUnit(static_cast<GLuint>(next_), texture);
  program.set(sampler, next_);
  ++next_;
}

}  // namespace strata
