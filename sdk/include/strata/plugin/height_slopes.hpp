#pragma once
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

class Layer;

// The GLSL of
//   vec4 <name>(SurfacePoint p)
// the height layer `height` at p with its slopes: the height in .r (m), its slopes east (.g) and north (.b) in
// metres of rise per metre along the ground, its coverage in .a; vec4(0) where it has no data. A layer that gives
// its slopes with its value (SlopedLayer: source.gdal's rasters) is sampled once, its slopes those of the texels
// the sample filters; any other five times, by central differences of its samples one footprint away each way
// along the ground (the footprint's longer axis, so that they filter like a pixel; one-sided where only one
// neighbour has data). `radius`: a GLSL expression for the body's radius in metres, usually a uniform the caller
// declares before it and sets in bind(). Paste it after height.glslOnce(). Also defines, from
// "strata/height_slopes.glsl", float slopeAngle(vec2 slopes, float exaggeration) (rad).
// composite.relief and sdk/examples/slope_mask build on it.
std::string heightSlopesGlsl(const std::string& name, const Layer& height, const std::string& radius);

}  // namespace strata
STRATA_EXPORTS_END
