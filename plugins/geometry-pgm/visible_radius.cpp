#include "visible_radius.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <strata/gl/texture.hpp>

#include "reference_spheres.hpp"

namespace strata::pgm {
namespace {

constexpr std::uint32_t kSignBit = 0x80000000u;
constexpr int kGroupSide = 16 * 4;  // texels a workgroup of pgm_least_radius.comp folds each way: 16 x 16 blocks of 4

// pgm_least_radius.comp's orderedBits of +infinity: what the minimum starts from, and stays at when no
// texel was covered.
constexpr std::uint32_t kUncovered = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::infinity()) | kSignBit;

// The inverse of pgm_least_radius.comp's orderedBits.
float fromOrderedBits(std::uint32_t ordered) {
  return std::bit_cast<float>((ordered & kSignBit) != 0u ? ordered & ~kSignBit : ~ordered);
}

}  // namespace

VisibleRadius::VisibleRadius(const ShaderLibrary& library, int samples)
    : program_({{GL_COMPUTE_SHADER, "geometry-pgm/pgm_least_radius.comp",
                 library.expand("geometry-pgm/pgm_least_radius.comp",
                                {{"STRATA_HEIGHTS_SAMPLER", glslSamplerFor(samples)},
                                 {"STRATA_HEIGHT_SAMPLES", std::to_string(samples)}})}}) {
  glCreateBuffers(1, &least_);
  glNamedBufferStorage(least_, sizeof(std::uint32_t), nullptr, 0);
  const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  const GLsizeiptr bytes = kSlots * sizeof(std::uint32_t);
  glCreateBuffers(1, &readback_);
  glNamedBufferStorage(readback_, bytes, nullptr, access);
  mapped_ = static_cast<const std::uint32_t*>(glMapNamedBufferRange(readback_, 0, bytes, access));
  if (!mapped_) throw std::runtime_error("the GL driver could not map the visible radius's readback buffer");
}

VisibleRadius::~VisibleRadius() {
  for (GLsync fence : fences_)
    if (fence) glDeleteSync(fence);
  glUnmapNamedBuffer(readback_);
  glDeleteBuffers(1, &readback_);
  glDeleteBuffers(1, &least_);
}

// The GPU runs commands in order, so a slot still in flight can be reused: its older copy lands first and
// the new fence covers both. The barrier makes the shader's atomics visible to the copy, and to the next
// frame's clear.
void VisibleRadius::reduce(GLuint heights, int width, int height, std::uint64_t frame) {
  glClearNamedBufferSubData(least_, GL_R32UI, 0, sizeof(std::uint32_t), GL_RED_INTEGER, GL_UNSIGNED_INT, &kUncovered);
  program_.use();
  program_.set("size", glm::ivec2(width, height));
  glBindTextureUnit(0, heights);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, least_);
  glDispatchCompute(GLuint(width + kGroupSide - 1) / kGroupSide, GLuint(height + kGroupSide - 1) / kGroupSide, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glCopyNamedBufferSubData(least_, readback_, 0, GLintptr(next_ * sizeof(std::uint32_t)), sizeof(std::uint32_t));
  if (fences_[next_]) glDeleteSync(fences_[next_]);
  fences_[next_] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  frames_[next_] = frame;
  next_ = (next_ + 1) % kSlots;
}

// Oldest first; fences signal in order, so the first one still running ends the search. The flush bit
// makes sure the fence reaches the GPU; a zero timeout never waits.
std::optional<double> VisibleRadius::latest() {
  for (std::size_t i = 0; i < kSlots; ++i) {
    const std::size_t slot = (next_ + i) % kSlots;
    if (!fences_[slot]) continue;
    const GLenum state = glClientWaitSync(fences_[slot], GL_SYNC_FLUSH_COMMANDS_BIT, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) break;
    collect(slot);
  }
  return latest_;
}

// The coherent mapping shows the copy once its fence has signalled.
void VisibleRadius::collect(std::size_t slot) {
  glDeleteSync(fences_[slot]);
  fences_[slot] = nullptr;
  const float least = fromOrderedBits(mapped_[slot]);
  latest_ = std::isinf(least) ? std::nullopt : std::optional<double>(least);
  latestFrame_ = frames_[slot];
}

// The turn is the largest angle between the two views' axes, from the trace of the relative rotation.
bool sameSight(const View& measured, const View& current, double minimumRadius) {
  if (measured.width != current.width || measured.height != current.height ||
      measured.verticalFov != current.verticalFov)
    return false;
  const double height = glm::length(current.eye) - minimumRadius;
  const glm::dmat3 turn = current.planetToEye * glm::transpose(measured.planetToEye);
  const double cosTurn = std::clamp(0.5 * (turn[0][0] + turn[1][1] + turn[2][2] - 1.0), -1.0, 1.0);
  return glm::length(current.eye - measured.eye) < kSightMove * height &&
         std::acos(cosTurn) < kSightTurn * current.verticalFov;
}

double primaryRadius(std::optional<double> latestHeight, double bodyRadius, double lowest, double eyeDistance) {
  return clampPrimaryRadius(bodyRadius + latestHeight.value_or(lowest), eyeDistance);
}

}  // namespace strata::pgm
