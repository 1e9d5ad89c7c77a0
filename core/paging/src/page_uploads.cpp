#include "page_uploads.hpp"

#include <cstring>
#include <stdexcept>

#include "page_atlas.hpp"

namespace strata::paging {
namespace {

constexpr GLuint64 kSecond = 1000000000;  // ns

}  // namespace

PageUploads::PageUploads(int ringSlots) : fences_(std::size_t(ringSlots), nullptr) {
  const GLbitfield access = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, GLsizeiptr(bytes()), nullptr, access);
  mapped_ = static_cast<std::byte*>(glMapNamedBufferRange(buffer_, 0, GLsizeiptr(bytes()), access));
  if (!mapped_) throw std::runtime_error("the GL driver could not map the page cache's upload buffer");
}

PageUploads::~PageUploads() {
  for (GLsync fence : fences_)
    if (fence) glDeleteSync(fence);
  if (buffer_) {
    glUnmapNamedBuffer(buffer_);
    glDeleteBuffers(1, &buffer_);
  }
}

void PageUploads::upload(GLuint atlas, PageFormat format, int atlasSlot, std::span<const std::byte> texels) {
  GLsync& fence = fences_[next_];
  if (fence) {  // the ring has come round: this slot's last upload must have been read
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, kSecond) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
  }
  const std::size_t offset = next_ * kPageBytes;
  std::memcpy(mapped_ + offset, texels.data(), kPageBytes);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage3D(atlas, 0, 0, 0, atlasSlot, kPageSide, kPageSide, 1, pixelFormatOf(format), pixelTypeOf(format),
                      reinterpret_cast<const void*>(offset));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  next_ = (next_ + 1) % fences_.size();
}

}  // namespace strata::paging
