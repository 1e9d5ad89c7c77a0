#pragma once
#include <strata/export.hpp>
#include <filesystem>
#include <vector>

#include <strata/gl/framebuffer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The end of a pipeline: a finished frame the host shows (a window) or saves (strata render).
class FrameOutput {
 public:
  virtual ~FrameOutput() = default;
  // The finished frame: RGBA8, sRGB-encoded, origin at the lower left.
  virtual const Framebuffer& frame() const = 0;
  // Writes the last rendered frame to `file`; throws strata::Error if it cannot be written.
  virtual void write(const std::filesystem::path& file) const = 0;
};

// Reads back colour attachment 0 of `framebuffer` as rows of RGBA8, top row first.
std::vector<unsigned char> readPixels(const Framebuffer& framebuffer);
// Writes RGBA8 rows (top row first) as an 8-bit PNG through GDAL; throws strata::Error naming the file.
void writePng(const std::filesystem::path& file, int width, int height,
              const std::vector<unsigned char>& rgba);

}  // namespace strata
STRATA_EXPORTS_END
