#pragma once
#include <algorithm>
#include <cstdint>
#include <strata/export.hpp>

#include <strata/body.hpp>
#include <strata/gl/framebuffer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// What a geometry generator made and spent on its last frame (`strata render --stats`, the benchmarks).
struct GeometryStatistics {
  int patches = 0;
  std::uint64_t vertices = 0;
  std::uint64_t triangles = 0;
  double visibilityMs = 0.0;     // CPU: choosing what to tessellate
  double subdivisionMs = 0.0;    // GPU: making the vertices
  double rasterisationMs = 0.0;  // GPU: drawing the deferred texturing buffer
};

// A geometry generator's output: the deferred texturing buffer it rasterised (its layout and how to make
// one: strata/gl/surface_buffer.hpp), and what it knows about its surface.
class SurfaceGeometry {
 public:
  virtual ~SurfaceGeometry() = default;
  virtual const Framebuffer& gbuffer() const = 0;
  // The heights its surface keeps within, once the node has opened (strata/plugin/height_input.hpp settles them):
  // the page cache measures distances to the ground they bound (groundLevelNear), and output.image composes
  // only within the outline of the body's radius plus `highest`, so a surface drawn above it is cut off at the
  // limb. The bare sphere: {0, 0}.
  virtual HeightRange heights() const { return {}; }
  // On the GL thread, after the frame: GPU times wait for the GPU to finish it.
  virtual GeometryStatistics statistics() const { return {}; }

  // Samples per pixel of the deferred buffer (multisample antialiasing): the most any reader asked for.
  // Readers ask while they are made (output.image's `antialiasing`), before any node creates its GPU
  // resources; the generator draws its buffer with samples().
  void requestSamples(int samples) { samples_ = std::max(samples_, samples); }
  int samples() const { return samples_; }

 private:
  int samples_ = 1;
};

}  // namespace strata
STRATA_EXPORTS_END
