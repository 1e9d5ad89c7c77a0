#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <strata/gl.hpp>
#include <strata/plugin/page_source.hpp>

#include "page_loader.hpp"

namespace strata::paging {

// The bytes of one slot of `format`'s atlas: colour RGBA16F; values RGBA32F, value x coverage and coverage as read
// and the value's slopes beside them (ValueSlopesPages), twice the kPageBytes a page takes on the CPU.
std::uint64_t slotBytes(PageFormat format);

// One format's cache texture ([Kooima 2008, §4.3.2]): a 2D array texture whose layers are page slots (in
// place of the source's n x m atlas, the layer index standing for row and column), and which page each slot
// holds. Slots are reused least recently used first; slots used this frame and pinned slots (the coarsest
// levels, which stand in for everything else) are never taken.
class PageAtlas {
 public:
  // The atlas of `capacity` slots, or of fewer, halving down to `fewest`, where the GL answers
  // GL_OUT_OF_MEMORY; none where even `fewest` do not fit.
  static std::unique_ptr<PageAtlas> largestFitting(PageFormat format, int capacity, int fewest);
  ~PageAtlas();
  PageAtlas(const PageAtlas&) = delete;
  PageAtlas& operator=(const PageAtlas&) = delete;

  GLuint texture() const { return texture_; }
  PageFormat format() const { return format_; }
  int capacity() const { return int(slots_.size()); }
  int resident() const;
  int pinned() const;

  // A free slot, or else the least recently used one not used in `frame` and not pinned, whose page
  // is returned in `evicted`. Empty when every slot is in use this frame.
  std::optional<int> claim(std::uint64_t frame, std::optional<LayerPage>& evicted);
  void hold(int slot, const LayerPage& page, std::uint64_t frame, bool pinned);
  void touch(int slot, std::uint64_t frame) { slots_[std::size_t(slot)].lastUsed = frame; }

 private:
  PageAtlas(PageFormat format, int capacity);  // texture() is 0 where the GL has no memory for it

  struct Slot {
    std::optional<LayerPage> page;
    std::uint64_t lastUsed = 0;
    bool pinned = false;
  };

  PageFormat format_;
  GLuint texture_ = 0;
  std::vector<Slot> slots_;
};

// GL's internal format, and the pixel format and type uploads use, for a page format.
GLenum internalFormatOf(PageFormat format);
GLenum pixelFormatOf(PageFormat format);
GLenum pixelTypeOf(PageFormat format);

}  // namespace strata::paging
