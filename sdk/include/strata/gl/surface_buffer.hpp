#pragma once
#include <array>
#include <strata/export.hpp>
#include <vector>

#include <strata/gl/framebuffer.hpp>
#include <strata/gl/shading_normal.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The deferred texturing buffer every geometry generator rasterises into ([Kooima 2008, §3.4.2]) and every
// per-pixel compositor and output reads: the contract between them, written once. Attachments:
//   color(0) longitude, latitude measured from View::reference (rad, longitude not wrapped), so that float
//            resolves them finely near the eye; kNoSurface's longitude where nothing was drawn. With
//            ShadingNormal::Stored RGBA32F, the shading normal (planet-fixed, of the displaced surface)
//            octahedrally encoded in .zw; with ShadingNormal::OfTheSphere RG32F, which reads as .zw = (0, 1)
//   depth    DEPTH32F: reversed depth (1 at the near plane), 0 where nothing was drawn
// then any attachments of the generator's own (`extra`, from color(1)), which readers of the buffer ignore.
// Shaders write and read color(0) through "strata/surface_buffer.glsl" alone ("strata/surface_buffer.frag"
// writes it): shadingNormalOf gives the stored normal or the sphere's, so readers need not know which. One
// attachment of 16 bytes a sample at most: llvmpipe's geometry pass with 4x multisampling took a quarter less
// time than with a second attachment for the shading normal, and the bare body's 8 bytes a sample a quarter less
// again (the peer benchmark's views, docs/benchmarks.md). With more than one sample per pixel (multisample
// antialiasing, SurfaceGeometry::samples) every attachment is multisampled: a fragment's values, interpolated at
// the pixel's centre, go to each sample it covers, and depth is tested per sample.
class SurfaceBuffer {
 public:
  // An attachment of a generator's own after the shared ones, and the value that clears it.
  struct Attachment {
    GLenum format;
    std::array<float, 4> clear;
  };

  // The longitude color(0) holds where no surface was drawn: far below any a surface has, and finite, so that
  // differences to it stay numbers (strata/surface_buffer.glsl's kNoSurface).
  static constexpr float kNoSurface = -1.0e30f;

  explicit SurfaceBuffer(ShadingNormal normal, std::vector<Attachment> extra = {});

  // Before drawing a frame of width x height, `samples` per pixel: (re)makes the attachments when the size
  // or the samples changed, binds the buffer with its viewport and clears it: no surface anywhere, depth at
  // infinity (0, reversed); and turns on the depth test its reversed depth takes (GL_GREATER: nearer is larger).
  void begin(int width, int height, int samples);
  // After drawing: the depth test off again.
  void end() const;
  const Framebuffer& framebuffer() const { return framebuffer_; }

 private:
  ShadingNormal normal_;
  std::vector<Attachment> extra_;
  Framebuffer framebuffer_;
};

}  // namespace strata
STRATA_EXPORTS_END
