// geometry.clipmap's height clipmaps (height_clipmaps.hpp), read by the surface's vertices
// ([Clasen & Hege 2006, §3.1, §4.2]): each level's window holds heights and slopes over longitude and latitude,
// at texels about as far apart as that level's rings' steps. The including program declares `float radius` and
// `STRATA_CLIPMAP_LEVELS`, the most levels a frame draws.
uniform sampler2DArray clipmapHeights;  // m
uniform sampler2DArray clipmapSlopes;   // rise per metre along the ground, east and north
uniform ivec2 clipmapLevels;            // the coarsest and the finest level with a window
// Per window, coarsest first: its south-west corner from the reference (xy) and its texel (zw), rad; where its
// texel 0 lies in its layer (xy, toroidal) and the layer (z).
uniform vec4 clipmapWindows[STRATA_CLIPMAP_LEVELS];
uniform ivec3 clipmapOffsets[STRATA_CLIPMAP_LEVELS];

// The height and slopes (rise per rad along the ground) of level `level`'s window at `fromReference` (rad from the
// reference), bilinear from four texel fetches, which give one vertex the same value in every invocation
// (strata/surface_point.glsl, bilinearTexels, says why).
vec3 clipmapSample(int level, vec2 fromReference) {
  int window = level - clipmapLevels.x;
  vec2 position = (fromReference - clipmapWindows[window].xy) / clipmapWindows[window].zw - 0.5;
  ivec2 low = ivec2(floor(position));
  vec2 f = position - vec2(low);
  int texels = textureSize(clipmapHeights, 0).x;
  ivec3 at = clipmapOffsets[window];
  ivec2 x = ((at.x + low.x + ivec2(0, 1)) % texels + texels) % texels;  // whole turns wrap from below too
  ivec2 y = ((at.y + low.y + ivec2(0, 1)) % texels + texels) % texels;
  vec3 corners[4];
  for (int k = 0; k < 4; ++k) {
    ivec3 texel = ivec3(x[k & 1], y[k >> 1], at.z);
    corners[k] = vec3(texelFetch(clipmapHeights, texel, 0).r, radius * texelFetch(clipmapSlopes, texel, 0).rg);
  }
  return mix(mix(corners[0], corners[1], f.x), mix(corners[2], corners[3], f.x), f.y);
}

// The height and slopes at `fromReference` for a vertex `colatitude` (theta~) from the nadir: its level's window,
// blended into the next coarser one's over the outer tenth of the level (two of the paper's twenty rings; Losasso
// and Hoppe's geometry clipmaps blend over a tenth of a level's width), so that the heights' filtering changes
// smoothly from ring to ring and a ring two levels share gets one value. Over a whole level the coarser window's
// texels blurred a cut's step in the heights past its edge. Level i spans theta~ from pi 2^-i to pi 2^-(i+1); the
// fill cap takes the finest.
vec3 clipmapHeight(vec2 fromReference, float colatitude) {
  float continuous = clamp(log2(PI / max(colatitude, 1e-30)), float(clipmapLevels.x), float(clipmapLevels.y) + 1.0);
  int level = min(int(floor(continuous)), clipmapLevels.y);
  vec3 fine = clipmapSample(level, fromReference);
  float coarser = level > clipmapLevels.x ? clamp(1.0 - 10.0 * (continuous - float(level)), 0.0, 1.0) : 0.0;
  return coarser > 0.0 ? mix(fine, clipmapSample(level - 1, fromReference), coarser) : fine;
}
