#include "scene_linear_pages.hpp"

#include <strata/gl/shader_library.hpp>

namespace strata::paging {
namespace {

constexpr const char* kFunction = "strata_toSceneLinear";
constexpr int kGroupSide = 16;  // the shader's local size

}  // namespace

std::optional<int> SceneLinearPages::add(const PageSource& source) {
  if (source.format() != PageFormat::Colour) return std::nullopt;
  const std::string glsl = source.toSceneLinearGlsl(kFunction);
  if (glsl.empty()) return std::nullopt;
  if (const auto known = numbers_.find(glsl); known != numbers_.end()) return known->second;
  const ShaderLibrary library;
  programs_.emplace_back(std::vector<ShaderProgram::Stage>{
      {GL_COMPUTE_SHADER, "strata/page_to_scene_linear.comp (" + source.name() + ")",
       library.expand("strata/page_to_scene_linear.comp", {{"STRATA_TO_SCENE_LINEAR_GLSL", glsl}})}});
  return numbers_[glsl] = int(programs_.size()) - 1;
}

void SceneLinearPages::convert(int conversion, GLuint atlas, int slot) const {
  const ShaderProgram& program = programs_[std::size_t(conversion)];
  program.use();
  program.set("slot", slot);
  glBindImageTexture(0, atlas, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
  const GLuint groups = (kPageSide + kGroupSide - 1) / kGroupSide;
  glDispatchCompute(groups, groups, 1);
  // The converted texels are sampled next, and the slot may be uploaded to again.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
}

}  // namespace strata::paging
