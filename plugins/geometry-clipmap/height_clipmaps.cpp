#include "height_clipmaps.hpp"

#include <algorithm>

#include <strata/plugin/layer.hpp>

namespace strata::clipmap {
namespace {

constexpr int kSpareLayers = 4;  // beyond the most levels a frame has asked for (height_clipmaps.hpp)

// `block` grown by a texel each way within a window `texels` across: the texels whose central differences read it.
TexelBlock grown(const TexelBlock& block, int texels) {
  const glm::ivec2 first = glm::max(block.first - 1, 0), last = glm::min(block.first + block.count + 1, texels);
  return {first, last - first};
}

}  // namespace

HeightClipmaps::HeightClipmaps(int texels, ShaderProgram fill, std::optional<ShaderProgram> slopes)
    : texels_(texels), fill_(std::move(fill)), slopes_(std::move(slopes)) {}

HeightClipmaps::~HeightClipmaps() { glDeleteTextures(2, textures_); }

// Textures of `layers` layers, holding no window yet.
void HeightClipmaps::allocate(int layers) {
  glDeleteTextures(2, textures_);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 2, textures_);
  glTextureStorage3D(textures_[0], 1, GL_R32F, texels_, texels_, layers);
  glTextureStorage3D(textures_[1], 1, GL_RG16F, texels_, texels_, layers);
  held_.assign(std::size_t(layers), {});
}

void HeightClipmaps::useFor(ShaderProgram& program, const View& view, double radius) const {
  program.use();
  program.set("referenceLonlat", glm::vec2(view.reference));
  program.set("radius", float(radius));
  program.set("texels", texels_);
}

void HeightClipmaps::update(const View& view, double radius, const Layer& layer, int coarsest, int finest) {
  if (finest - coarsest + 1 > int(held_.size())) allocate(finest - coarsest + 1 + kSpareLayers);
  const std::uint64_t revision = layer.revision();
  if (revision_ != revision) std::fill(held_.begin(), held_.end(), HeldWindow{});
  revision_ = revision;
  coarsest_ = coarsest;
  finest_ = finest;
  std::vector<std::pair<int, std::vector<TexelBlock>>> moved;  // per level, the blocks it moved in
  for (int level = coarsest; level <= finest; ++level) {
    HeldWindow& held = held_[std::size_t(level) % held_.size()];
    const HeightWindow wanted = heightWindow(level, view.reference, texels_);
    moved.emplace_back(
        level, texelsToSample(held.level == level ? std::optional(held.window) : std::nullopt, wanted, texels_));
    held = {level, wanted};
  }
  glBindImageTexture(0, textures_[0], 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32F);
  glBindImageTexture(1, textures_[1], 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
  useFor(fill_, view, radius);
  TextureUnits units;
  layer.bind(fill_, units);
  for (const auto& [level, blocks] : moved)
    for (const TexelBlock& block : blocks) {
      const int at = int(std::size_t(level) % held_.size());
      dispatch(fill_, at, held_[std::size_t(at)].window, block, view.reference);
    }
  if (slopes_) differenceSlopes(moved, view, radius);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void HeightClipmaps::differenceSlopes(const std::vector<std::pair<int, std::vector<TexelBlock>>>& moved,
                                      const View& view, double radius) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  useFor(*slopes_, view, radius);
  for (const auto& [level, blocks] : moved)
    for (const TexelBlock& block : blocks) {
      const int at = int(std::size_t(level) % held_.size());
      slopes_->set("wholeTurn", int(held_[std::size_t(at)].window.wholeTurn));
      dispatch(*slopes_, at, held_[std::size_t(at)].window, grown(block, texels_), view.reference);
    }
}

void HeightClipmaps::dispatch(ShaderProgram& program, int layer, const HeightWindow& window, const TexelBlock& block,
                              glm::dvec2 reference) const {
  program.set("layer", layer);
  program.set("first", block.first);
  program.set("count", block.count);
  program.set("offset", textureOffset(window, texels_));
  program.set("cornerFromReference", glm::vec2(cornerFromReference(window, reference)));
  program.set("texel", glm::vec2(window.texel));
  glDispatchCompute(GLuint(block.count.x + 7) / 8, GLuint(block.count.y + 7) / 8, 1);  // local size 8 x 8
}

void HeightClipmaps::bind(ShaderProgram& surface, TextureUnits& units, glm::dvec2 reference) const {
  units.bind(surface, "clipmapHeights", textures_[0]);
  units.bind(surface, "clipmapSlopes", textures_[1]);
  surface.set("clipmapLevels", glm::ivec2(coarsest_, finest_));
  for (int level = coarsest_; level <= finest_; ++level) {
    const int at = int(std::size_t(level) % held_.size());
    const HeightWindow& window = held_[std::size_t(at)].window;
    const std::string index = "[" + std::to_string(level - coarsest_) + "]";
    surface.set("clipmapWindows" + index,
                glm::vec4(glm::vec2(cornerFromReference(window, reference)), glm::vec2(window.texel)));
    surface.set("clipmapOffsets" + index, glm::ivec3(textureOffset(window, texels_), at));
  }
}

}  // namespace strata::clipmap
