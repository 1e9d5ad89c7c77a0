// composite.slope_mask's paint: `paint` of `colour` laid over `surface` where the ground's slope (rad) is
// steeper than `threshold`, weighted by the heights' coverage (no data, no paint). Values are not
// premultiplied: coverage is alpha. The layer's own GLSL (slope_mask.cpp) samples its inputs and calls it.
vec4 slopeMaskOver(vec4 surface, vec4 height, float slope, float threshold, vec3 colour, float opacity) {
  if (height.a <= 0.0 || slope <= threshold) return surface;
  float paint = opacity * height.a, rest = surface.a * (1.0 - paint);
  float coverage = paint + rest;
  return coverage > 0.0 ? vec4((colour * paint + surface.rgb * rest) / coverage, coverage) : vec4(0.0);
}
