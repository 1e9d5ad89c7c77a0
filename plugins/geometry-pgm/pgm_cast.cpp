#include "pgm_cast.hpp"

#include <cmath>
#include <numbers>

namespace strata::pgm {

glm::dvec3 gridRay(const SamplingCamera& camera, glm::ivec2 size, int column, int row) {
  const double across = double(column) / (size.x - 1), up = double(row) / (size.y - 1);
  return glm::normalize(glm::dvec3(camera.left + across * (camera.right - camera.left),
                                   camera.bottom + up * (camera.top - camera.bottom), -camera.near));
}

// The secondary sphere's constants go up as tau_s - b and gamma0 = pi/2 - tau_s, formed in double: in
// float each difference would lose its leading digits [Mahsman 2010, §3.6.4].
void useCast(const ShaderProgram& program, const SamplingCamera& camera, const CrossSection& view,
             const glm::dmat3& samplingToLocal, glm::ivec2 size) {
  const double outermost = 0.5 * std::numbers::pi - view.secondaryTangent;
  program.use();
  program.set("gridSize", size);
  program.set("frustum", glm::vec4(camera.left, camera.right, camera.bottom, camera.top));
  program.set("near", float(camera.near));
  program.set("samplingToLocal", glm::mat3(samplingToLocal));
  program.set("altitude", float(view.altitude));
  program.set("relativeAltitude", float(view.altitude / view.primaryRadius));
  program.set("primaryRadius", float(view.primaryRadius));
  program.set("primaryTangent", float(view.primaryTangent));
  program.set("horizonSine", float(std::sin(view.primaryTangent)));
  program.set("horizonCosine", float(std::cos(view.primaryTangent)));
  program.set("blendStart", float(view.blendStart));
  program.set("hasSecondary", int(view.secondaryRadius > 0.0));
  program.set("secondarySpan", float(view.secondaryTangent - view.blendStart));
  program.set("outermostAngle", float(outermost));
  program.set("outermostTangent", float(std::tan(outermost)));
}

CastBuffers::CastBuffers(glm::ivec2 capacity) : capacity_(capacity) {
  glCreateBuffers(GLsizei(buffers_.size()), buffers_.data());
  for (const GLuint buffer : buffers_)
    glNamedBufferStorage(buffer, GLsizeiptr(capacity.x) * capacity.y * GLsizeiptr(sizeof(glm::vec4)), nullptr, 0);
}

CastBuffers::~CastBuffers() { glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data()); }

void CastBuffers::bind(GLuint first) const {
  for (GLuint i = 0; i < buffers_.size(); ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, first + i, buffers_[i]);
}

void CastBuffers::cast(glm::ivec2 size) const {
  bind(0);
  glDispatchCompute(GLuint(size.x + 7) / 8, GLuint(size.y + 7) / 8, 1);  // local size 8 x 8
}

std::vector<CastBuffers::Point> CastBuffers::read() const {
  const std::size_t count = std::size_t(capacity_.x) * std::size_t(capacity_.y);
  std::vector<glm::vec4> normals(count), positions(count);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffers_[0], 0, GLsizeiptr(count * sizeof(glm::vec4)), normals.data());
  glGetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(count * sizeof(glm::vec4)), positions.data());
  std::vector<Point> points(count);
  for (std::size_t i = 0; i < count; ++i) points[i] = {normals[i], positions[i]};
  return points;
}

}  // namespace strata::pgm
