#include "scene_linear_pages.hpp"

#include <strata/gl/shader_library.hpp>

#include "slot_pass.hpp"

namespace strata::paging {
namespace {

constexpr const char* kFunction = "strata_toSceneLinear";

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
  runOverSlot(programs_[std::size_t(conversion)], atlas, GL_RGBA16F, slot);
}

}  // namespace strata::paging
