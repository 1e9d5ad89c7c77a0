#include "value_slopes_pages.hpp"

#include <strata/gl/shader_library.hpp>
#include <strata/plugin/page_pyramid.hpp>

namespace strata::paging {
namespace {

constexpr int kGroupSide = 16;  // the shader's local size

}  // namespace

ValueSlopesPages::ValueSlopesPages()
    : program_({{GL_COMPUTE_SHADER, "strata/page_value_slopes.comp",
                 ShaderLibrary().expand("strata/page_value_slopes.comp", {})}}) {}

void ValueSlopesPages::compute(GLuint atlas, int slot) const {
  program_.use();
  program_.set("slot", slot);
  glBindImageTexture(0, atlas, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  const GLuint groups = (kPageSide + kGroupSide - 1) / kGroupSide;
  glDispatchCompute(groups, groups, 1);
  // The slopes are sampled next, and the slot may be uploaded to again.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
}

}  // namespace strata::paging
