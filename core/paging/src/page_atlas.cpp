#include "page_atlas.hpp"

#include <algorithm>
#include <utility>

namespace strata::paging {

GLenum internalFormatOf(PageFormat format) { return format == PageFormat::Colour ? GL_RGBA16F : GL_RGBA32F; }
GLenum pixelFormatOf(PageFormat format) { return format == PageFormat::Colour ? GL_RGBA : GL_RG; }
GLenum pixelTypeOf(PageFormat format) { return format == PageFormat::Colour ? GL_HALF_FLOAT : GL_FLOAT; }

std::uint64_t slotBytes(PageFormat format) {
  return std::uint64_t(kPageSide) * kPageSide * (format == PageFormat::Colour ? 8 : 16);
}

namespace {

// Whether the GL refused the storage just asked for: GL_OUT_OF_MEMORY is then an answer, not a fault, so
// the debug output that reports GL errors is muted around the request.
template <typename Request>
bool outOfMemory(Request&& request) {
  while (glGetError() != GL_NO_ERROR) {
  }
  const bool debugging = glIsEnabled(GL_DEBUG_OUTPUT);
  glDisable(GL_DEBUG_OUTPUT);
  request();
  const bool refused = glGetError() == GL_OUT_OF_MEMORY;
  if (debugging) glEnable(GL_DEBUG_OUTPUT);
  return refused;
}

}  // namespace

std::unique_ptr<PageAtlas> PageAtlas::largestFitting(PageFormat format, int capacity, int fewest) {
  while (true) {
    std::unique_ptr<PageAtlas> atlas(new PageAtlas(format, capacity));
    if (atlas->texture_) return atlas;
    if (capacity <= fewest) return nullptr;
    capacity = std::max(fewest, capacity / 2);
  }
}

PageAtlas::PageAtlas(PageFormat format, int capacity) : format_(format), slots_(std::size_t(capacity)) {
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture_);
  if (outOfMemory([&] { glTextureStorage3D(texture_, 1, internalFormatOf(format), kPageSide, kPageSide, capacity); })) {
    glDeleteTextures(1, &texture_);
    texture_ = 0;
    return;
  }
  // Shaders filter colour pages bilinearly by the sampler, within a slot, in fragment stages, and the rest by
  // hand with texel fetches (paged_texture.glsl, slotBilinear); no mip levels: pages of each level have slots.
  const GLint filter = format == PageFormat::Colour ? GL_LINEAR : GL_NEAREST;
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, filter);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, filter);
}

PageAtlas::~PageAtlas() {
  if (texture_) glDeleteTextures(1, &texture_);
}

int PageAtlas::resident() const {
  return int(std::ranges::count_if(slots_, [](const Slot& slot) { return slot.page.has_value(); }));
}

int PageAtlas::pinned() const {
  return int(std::ranges::count_if(slots_, [](const Slot& slot) { return slot.pinned; }));
}

std::optional<int> PageAtlas::claim(std::uint64_t frame, std::optional<LayerPage>& evicted) {
  evicted.reset();
  std::optional<int> oldest;
  for (int i = 0; i < capacity(); ++i) {
    const Slot& slot = slots_[std::size_t(i)];
    if (!slot.page) return i;
    if (slot.pinned || slot.lastUsed >= frame) continue;
    if (!oldest || slot.lastUsed < slots_[std::size_t(*oldest)].lastUsed) oldest = i;
  }
  if (oldest) evicted = std::exchange(slots_[std::size_t(*oldest)].page, std::nullopt);
  return oldest;
}

void PageAtlas::hold(int slot, const LayerPage& page, std::uint64_t frame, bool pinned) {
  slots_[std::size_t(slot)] = {page, frame, pinned};
}

}  // namespace strata::paging
