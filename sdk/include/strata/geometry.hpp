#pragma once
#include <strata/gl/framebuffer.hpp>

namespace strata {

// The deferred texturing buffer a geometry generator rasterises (seed 000, section 3.4.2), read by
// every per-pixel compositor. Attachments:
//   color(0) RGBA32F: longitude, latitude (rad, longitude not wrapped), planet-fixed unit normal x, y
//   color(1) RGBA16F: shading normal (planet-fixed, of the displaced surface) xyz, coverage (1 on the body)
//   depth    DEPTH32F: reversed depth (1 at the near plane), 0 where nothing was drawn
class SurfaceGeometry {
 public:
  virtual ~SurfaceGeometry() = default;
  virtual const Framebuffer& gbuffer() const = 0;
};

}  // namespace strata
