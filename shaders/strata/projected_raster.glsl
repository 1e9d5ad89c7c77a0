// Sampling a raster through a projection: the pieces every projected layer shares. A layer's own code
// maps longitude/latitude to texture coordinates (its projection, then its geotransform) and calls these.
#include "strata/constants.glsl"
#include "strata/surface_point.glsl"

// Whether texture coordinates (.z: the projection is defined there) fall on the raster. A raster that
// wraps around the body is inside at every u.
bool insideTexture(vec3 uv, bool repeatX) {
  return uv.z > 0.0 && uv.y >= 0.0 && uv.y <= 1.0 && (repeatX || (uv.x >= 0.0 && uv.x <= 1.0));
}

// A footprint step away from `lonlat`, kept off the far side of the poles where projections are undefined.
vec2 steppedLonlat(vec2 lonlat, vec2 step) {
  return vec2(lonlat.x + step.x, clamp(lonlat.y + step.y, -0.5 * PI, 0.5 * PI));
}

// The change of texture coordinates over one footprint step, by finite differences through the
// projection, so that any projection works without derivatives of its own. Of the forward and the
// backward difference the shorter is taken: beside an interruption of the map (HEALPix's polar
// triangles) or its east/west seam the other one jumps across the map and would blur the sample.
vec2 footprintStep(vec3 at, vec3 ahead, vec3 behind, bool repeatX) {
  vec2 forward = ahead.xy - at.xy, backward = at.xy - behind.xy;
  if (repeatX) {
    forward.x -= round(forward.x);
    backward.x -= round(backward.x);
  }
  if (ahead.z == 0.0) return backward;
  if (behind.z == 0.0) return forward;
  return dot(forward, forward) < dot(backward, backward) ? forward : backward;
}

// A one-channel layer's filtered texel `t` (value x coverage in .r, coverage in .g, the value's slopes per level-0
// texel x coverage in .b and .a: strata/paged_texture.glsl) as a value with its slopes: raw x scale + offset in .r,
// its change per radian along the ground east (.g) and north (.b), coverage in .a; vec4(0) where there is no data.
// Both are their texels' means weighted by coverage: beside no data, the data's own. `east` and `north`: level-0
// texels per radian along the ground each way.
vec4 slopedValue(vec4 t, vec2 east, vec2 north, vec2 scaleOffset) {
  if (t.g <= 0.0) return vec4(0.0);
  vec2 change = vec2(dot(t.ba, east), dot(t.ba, north)) / t.g;
  return vec4(t.r / t.g * scaleOffset.x + scaleOffset.y, change * scaleOffset.x, t.g);
}
