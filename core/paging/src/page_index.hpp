#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <strata/gl.hpp>
#include <strata/plugin/page_pyramid.hpp>

namespace strata::paging {

// The index of page references every paged layer shares ([Kooima 2008, §4.3.2]: the "mipmap index
// texture"), one R32UI texel per page of every level of every layer, in a texture kIndexWidth wide:
//   the layer's first `levels` entries: where each level's entries start
//   then per level, row-major, per page: 0 where nothing is loaded, else
//     bit 31 set | level of the page referenced << 16 | atlas slot
// A page that is not loaded references its nearest loaded ancestor, the proxy that stands in for it;
// the referenced level tells the shader to rescale into that page.
class PageIndex {
 public:
  static constexpr int kIndexWidth = 4096;

  PageIndex() = default;
  ~PageIndex();
  PageIndex(const PageIndex&) = delete;
  PageIndex& operator=(const PageIndex&) = delete;

  // Adds a layer's pyramid before allocate(); returns the index of its first entry. Throws
  // std::length_error for a pyramid with more pages than the index can still hold.
  unsigned add(const PagePyramid& pyramid);
  // Creates the texture for every layer added.
  void allocate();
  // Records that `key` of layer `layer` (in the order added) is in atlas slot `slot`, or no longer
  // loaded, and updates the references of the page and of every page below it.
  void place(int layer, const PageKey& key, std::optional<int> slot);
  // Copies changed entries to the texture.
  void upload();

  GLuint texture() const { return texture_; }
  std::size_t bytes() const { return entries_.size() * sizeof(std::uint32_t); }

 private:
  struct Layer {
    PagePyramid pyramid;
    unsigned base = 0;
  };
  std::size_t entryOf(const Layer& layer, const PageKey& key) const;
  std::uint32_t referenceFor(const Layer& layer, const PageKey& key) const;

  std::vector<Layer> layers_;
  std::vector<std::uint32_t> entries_;
  std::vector<std::int32_t> slots_;  // per entry: the page's own slot, -1 when not loaded
  std::size_t dirtyBegin_ = 0, dirtyEnd_ = 0;
  GLuint texture_ = 0;
};

}  // namespace strata::paging
