#include "slot_pass.hpp"

#include <strata/plugin/page_pyramid.hpp>

namespace strata::paging {
namespace {

constexpr int kGroupSide = 16;  // the passes' local size

}  // namespace

void runOverSlot(const ShaderProgram& program, GLuint atlas, GLenum format, int slot) {
  program.use();
  program.set("slot", slot);
  glBindImageTexture(0, atlas, 0, GL_TRUE, 0, GL_READ_WRITE, format);
  const GLuint groups = (kPageSide + kGroupSide - 1) / kGroupSide;
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, format);
}

}  // namespace strata::paging
