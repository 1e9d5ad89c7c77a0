#pragma once
#include <filesystem>
#include <strata/export.hpp>
#include <vector>

#include <strata/gl/framebuffer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class SurfaceGeometry;

// The end of a pipeline: a finished frame the host shows (a window) or saves (strata render).
class FrameOutput {
 public:
  virtual ~FrameOutput() = default;
  // The finished frame: RGBA8, sRGB-encoded, origin at the lower left.
  virtual const Framebuffer& frame() const = 0;
  // Writes the last rendered frame to `file`; throws strata::Error if it cannot be written.
  virtual void write(const std::filesystem::path& file) const = 0;
  // The geometry the frame was composed over, whose deferred texturing buffer (strata/gl/surface_buffer.hpp) says
  // what lies under each pixel and how far away: for picking and range images. nullptr for an output
  // composed over none.
  virtual const SurfaceGeometry* surface() const { return nullptr; }
};

// Reads back colour attachment 0 of `framebuffer` as rows of RGBA8, top row first.
std::vector<unsigned char> readPixels(const Framebuffer& framebuffer);
// Reads back the depth attachment of `framebuffer` as rows of floats, top row first: a geometry's reversed
// depth (View::projection: near / distance along the view axis, 0 where nothing was drawn). The depth at
// each pixel's centre: a multisampled framebuffer (output.image's `antialiasing`) has none, and is refused
// (std::invalid_argument).
std::vector<float> readDepth(const Framebuffer& framebuffer);
// The image formats frames are written in, chosen by the file's extension.
enum class ImageFormat { Png, Tiff };
// .png: PNG; .tif, .tiff: TIFF (any case). Throws strata::Error naming the file for any other extension.
ImageFormat imageFormatOf(const std::filesystem::path& file);
// Writes RGBA8 rows (top row first) as an 8-bit image through GDAL, in the format its extension names
// (imageFormatOf); throws strata::Error naming the file. It writes `file` as given: callers that must not
// leave a partial image under a user's name write into a ScratchDirectory (strata/host/output_file.hpp).
void writeImage(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba);

}  // namespace strata
STRATA_EXPORTS_END
