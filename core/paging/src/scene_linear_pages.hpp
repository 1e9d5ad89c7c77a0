#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/page_source.hpp>

namespace strata::paging {

// Converts colour pages in their atlas slots to scene-linear, each from the colour space its source encodes
// it in (PageSource::toSceneLinearGlsl, OpenColorIO's GLSL), right after the page is uploaded: a compute pass
// over the slot (shaders/strata/page_to_scene_linear.comp). One program per distinct conversion, compiled
// when a source is added, not per page or per frame. On the GL thread.
class SceneLinearPages {
 public:
  // The number of `source`'s conversion, or none where its pages need none (scene-linear already, or
  // not colour).
  std::optional<int> add(const PageSource& source);
  // Converts the page in `slot` of the RGBA16F array texture `atlas` by conversion `conversion`.
  void convert(int conversion, GLuint atlas, int slot) const;

 private:
  std::map<std::string, int> numbers_;  // by the conversion's GLSL
  std::vector<ShaderProgram> programs_;
};

}  // namespace strata::paging
