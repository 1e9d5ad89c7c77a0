#version 450 core
// The value's slopes of one page of a one-channel layer, in its atlas slot, right after its upload: each texel
// of value x coverage (.r) and coverage (.g) gets the central differences of the value (r / g) along slot x and
// y, times its coverage as the value is, in .b and .a, so that a filtered sample carries its gradient in the
// texels it reads (strata/paged_texture.glsl; SlopedLayer): its four texels' differences mixed bilinearly vary
// continuously across the cell, where the bilinear patch's own gradient jumps at every texel edge. One-sided
// where one neighbour has no data or lies beyond the slot (its edge, within half a texel of the page's seam), 0
// where neither has.
layout(local_size_x = 16, local_size_y = 16) in;

// The upload wrote .r and .g (and 0 and 1 in .b and .a); this pass reads the neighbours' .r and .g, which it
// leaves as they are, and writes each texel's .b and .a.
layout(binding = 0, rgba32f) uniform image2DArray atlas;
uniform int slot;

// The texel's value and whether it has any (coverage above 0), or none beyond the slot's edges.
vec2 valueAt(ivec2 texel, ivec2 size) {
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return vec2(0.0);
  vec4 stored = imageLoad(atlas, ivec3(texel, slot));
  return stored.g > 0.0 ? vec2(stored.r / stored.g, 1.0) : vec2(0.0);
}

// The value's change over one texel from `behind` to `ahead` (value, has data), `here` between.
float difference(vec2 behind, float here, vec2 ahead) {
  if (ahead.y > 0.0 && behind.y > 0.0) return 0.5 * (ahead.x - behind.x);
  if (ahead.y > 0.0) return ahead.x - here;
  return behind.y > 0.0 ? here - behind.x : 0.0;
}

void main() {
  ivec2 size = imageSize(atlas).xy, texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  vec4 stored = imageLoad(atlas, ivec3(texel, slot));
  vec2 slopes = vec2(0.0);
  if (stored.g > 0.0) {
    float here = stored.r / stored.g;
    slopes = vec2(difference(valueAt(texel - ivec2(1, 0), size), here, valueAt(texel + ivec2(1, 0), size)),
                  difference(valueAt(texel - ivec2(0, 1), size), here, valueAt(texel + ivec2(0, 1), size)));
  }
  imageStore(atlas, ivec3(texel, slot), vec4(stored.rg, slopes * stored.g));
}
