#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <strata/gl.hpp>
#include <strata/plugin/page_source.hpp>

namespace strata::paging {

// Copies pages into atlas slots through a ring of pixel-buffer-object slots, persistently mapped (a GL 4.5
// form of the asynchronous pixel-buffer-object uploads of [Kooima 2008, §4.3.2]): the CPU copy goes into
// driver memory and the transfer runs without blocking the frame. A fence per ring slot keeps a slot from
// being overwritten before the GPU has read it.
class PageUploads {
 public:
  explicit PageUploads(int ringSlots);
  ~PageUploads();
  PageUploads(const PageUploads&) = delete;
  PageUploads& operator=(const PageUploads&) = delete;

  void upload(GLuint atlas, PageFormat format, int atlasSlot, std::span<const std::byte> texels);
  std::size_t bytes() const { return fences_.size() * kPageBytes; }

 private:
  GLuint buffer_ = 0;
  std::byte* mapped_ = nullptr;
  std::vector<GLsync> fences_;
  std::size_t next_ = 0;
};

}  // namespace strata::paging
