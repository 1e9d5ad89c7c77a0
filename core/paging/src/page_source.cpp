#include <strata/plugin/page_source.hpp>

namespace strata {

LevelWindow PageSource::gridOf(const PageKey& key) const {
  return {key.level, 0, 0, pyramid().levelWidth(key.level), pyramid().levelHeight(key.level)};
}

std::optional<glm::ivec2> PageSource::texelBeside(const PageKey&, glm::ivec2) const { return std::nullopt; }

std::string PageSource::toSceneLinearGlsl(const std::string&) const { return {}; }

}  // namespace strata
