// A point of a body's surface as layers sample it: where it is, and the footprint of the sample (how far
// longitude and latitude move to the next pixel or vertex), so each layer picks its own level of detail.
struct SurfacePoint {
  vec2 lonlat;         // rad; longitude is not wrapped and may lie outside [-pi, pi]
  vec3 normal;         // planet-fixed unit normal of the undisplaced sphere (+z north, +x at longitude 0)
  vec2 lonlatDx;       // change of lonlat to the next sample along x (longitude wrap already removed)
  vec2 lonlatDy;       // the same along y
  // lonlat measured from the frame's reference, the point below the eye (View::reference): float
  // resolves it to micrometres near the eye, where lonlat itself resolves about a metre on Earth.
  vec2 fromReference;
};

// The sample's footprint along the ground, rad: the longer of its two steps, so that what is measured over
// it (a height's slopes) spans a pixel.
float groundFootprint(SurfacePoint p) {
  float c = cos(p.lonlat.y);
  return max(max(length(vec2(p.lonlatDx.x * c, p.lonlatDx.y)), length(vec2(p.lonlatDy.x * c, p.lonlatDy.y))), 1e-12);
}

#include "strata/anisotropic_taps.glsl"

#ifdef STRATA_GEOMETRY_STAGE
// Bilinear filtering done by hand on one mip level, with texel fetches. Mesa's llvmpipe gave one vertex
// different filtered values in different invocations of a vertex shader (textureLod and textureGrad
// alike), which cracked the displaced mesh; fetches are exact everywhere. `repeatX`: wrap across the
// antimeridian rather than clamp.
vec4 bilinearTexels(sampler2D image, vec2 uv, int level, bool repeatX) {
  ivec2 size = textureSize(image, level);
  vec2 position = uv * vec2(size) - 0.5;
  ivec2 low = ivec2(floor(position));
  vec2 f = position - vec2(low);
  ivec2 high = low + 1;
  ivec2 x = repeatX ? (ivec2(low.x, high.x) % size.x + size.x) % size.x : clamp(ivec2(low.x, high.x), 0, size.x - 1);
  ivec2 y = clamp(ivec2(low.y, high.y), 0, size.y - 1);
  return mix(mix(texelFetch(image, ivec2(x[0], y[0]), level), texelFetch(image, ivec2(x[1], y[0]), level), f.x),
             mix(texelFetch(image, ivec2(x[0], y[1]), level), texelFetch(image, ivec2(x[1], y[1]), level), f.x), f.y);
}
#endif

// Samples `image` at `uv` over a footprint given as texture-coordinate steps along x and y. Fragment
// stages filter anisotropically by hand (strata/anisotropic_taps.glsl), each tap by the sampler at its width;
// geometry stages (heights sampled by the compute pass, which has no derivatives) filter trilinearly by
// hand at the level of the longer step. `repeatX`: the sampler wraps, as the geometry stages' fetches do.
vec4 sampleFootprint(sampler2D image, vec2 uv, vec2 stepX, vec2 stepY, bool repeatX) {
#ifdef STRATA_GEOMETRY_STAGE
  vec2 size = vec2(textureSize(image, 0));
  float lod = clamp(log2(max(length(stepX * size), length(stepY * size))), 0.0, float(textureQueryLevels(image) - 1));
  int level = int(floor(lod));
  return mix(bilinearTexels(image, uv, level, repeatX),
             bilinearTexels(image, uv, min(level + 1, textureQueryLevels(image) - 1), repeatX), fract(lod));
#else
  vec2 size = vec2(textureSize(image, 0));
  AnisotropicTaps taps = anisotropicTaps(stepX * size, stepY * size);
  vec2 across = normalize(taps.major + vec2(1e-30, 0.0)) * taps.width / size;  // the tap's width, as a gradient
  vec4 sum = vec4(0.0);
  int tap = 0;
  do {  // do-while: llvmpipe runs a loop's body once more, masked, when its test comes first
    sum += textureGrad(image, uv + tapOffset(taps, tap) / size, across, vec2(0.0));
  } while (++tap < taps.count);
  return sum / float(taps.count);
#endif
}
