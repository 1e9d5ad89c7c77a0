#pragma once
#include <cstdint>
#include <strata/export.hpp>

#include <strata/error.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The pipeline's `cache:` section (docs/data.md, "How the cache is sized").
struct PageCacheSettings {
  // GPU memory for pages, upload staging included. A quarter of a 1 GB GPU: the rest stays free for
  // framebuffers, G-buffers and meshes. 256 MiB hold about 115 pages of 2.1 MB, several screens' worth.
  std::uint64_t budgetBytes = 256ull << 20;
  // Pages copied to the GPU per frame: 8 x 2.1 MB is 17 MB a frame, 1 GB/s at 60 Hz, well inside what
  // PCIe and llvmpipe's memcpy move without stalling the frame.
  int uploadsPerFrame = 8;
  // Threads reading pages with GDAL. Two keep a compressed COG on an SSD busy while leaving the other
  // cores to the frame's workers.
  int loaderThreads = 2;
  // Load the pages the view half a second on will want (FrameState::ahead) into the room the view's own leave:
  // the paper's speculative prefetch [Cignoni et al. 2003, §4.4], so that a moving view finds its pages read.
  bool prefetch = true;
  SourceLocation where;  // the `cache:` section, for messages
};

}  // namespace strata
STRATA_EXPORTS_END
