#version 450 core
#define STRATA_GEOMETRY_STAGE
STRATA_PROGRAM_DEFINES
// Samples a block of one level's height clipmap window (height_windows.hpp) from the height layer
// ([Clasen & Hege 2006, §3.1, §4.1]): each texel's height at its centre, over a circle on the ground that covers
// the texel (§4.3: the pyramid filtered in world space, its kernel a circle on the ground given in longitude and
// latitude), stored where the toroidal window keeps that texel, with its slopes where the layer gives them with its
// value (SlopedLayer: a raster's, interpolated from central differences of its own texels); else
// clipmap_slopes.comp differences the heights. Texel centres are measured from the frame's reference in float from
// a corner worked out in double, as every sample of every layer is (docs/architecture.md, "Precision").
#include "strata/constants.glsl"
#include "strata/surface_point.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform writeonly image2DArray heights;  // m
#ifdef STRATA_HEIGHT_SLOPED_FUNCTION
layout(rg16f, binding = 1) uniform writeonly image2DArray slopes;  // rise per metre along the ground
#endif

uniform vec2 referenceLonlat;     // rad: the point below the eye (View::reference)
uniform float radius;             // m
uniform int layer;                // the window's layer of the textures
uniform ivec2 first;              // the block's first texel of the window
uniform ivec2 count;              // the block's texels
uniform ivec2 offset;             // where the window's texel 0 lies in its layer (textureOffset)
uniform int texels;               // the window's width and height
uniform vec2 cornerFromReference; // rad: the window's south-west corner from the reference
uniform vec2 texel;               // rad of longitude and latitude

STRATA_HEIGHT_LAYER_GLSL
#include "strata/height_sampling.glsl"

void main() {
  ivec2 invocation = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(invocation, count))) return;
  ivec2 k = first + invocation;
  vec2 fromReference = cornerFromReference + (vec2(k) + 0.5) * texel;
  float latitude = referenceLonlat.y + fromReference.y;
  if (abs(latitude) > 0.5 * PI) {  // a texel beyond a pole, read only by a bilinear sample at the pole: the pole's
    latitude = sign(latitude) * 0.5 * PI;
    fromReference.y = latitude - referenceLonlat.y;
  }
  float longitude = referenceLonlat.x + fromReference.x;
  vec3 normal = vec3(cos(latitude) * cos(longitude), cos(latitude) * sin(longitude), sin(latitude));
  float spacing = max(texel.y, texel.x * cos(latitude));
  ivec3 stored = ivec3((offset + k) % texels, layer);
#ifdef STRATA_HEIGHT_SLOPED_FUNCTION
  vec4 sampled = slopedHeightAt(fromReference, normal, spacing);
  imageStore(heights, stored, vec4(sampled.r));
  imageStore(slopes, stored, vec4(sampled.gb / radius, 0.0, 0.0));
#else
  imageStore(heights, stored, vec4(heightAt(fromReference, normal, spacing)));
#endif
}
