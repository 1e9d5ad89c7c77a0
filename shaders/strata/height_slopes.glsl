// The pieces of strata::heightSlopesGlsl (strata/plugin/height_slopes.hpp): a height layer's slopes at a surface
// point, from its samples one footprint away along the ground each way, for height layers that do not give their
// slopes with their value (SlopedLayer).

// The point `step` (rad of longitude, latitude) from `p`, with the same footprint. Its normal is turned
// from p's along the local east and north rather than rebuilt from lonlat, which float resolves to about a
// metre on Earth.
#include "strata/local_frame.glsl"

SurfacePoint slopeNeighbour(SurfacePoint p, vec2 step) {
  mat3 local = eastNorthUp(p.lonlat.x, p.normal);
  p.normal = normalize(p.normal + local[0] * (step.x * cos(p.lonlat.y)) + local[1] * step.y);
  p.lonlat += step;
  p.fromReference += step;
  return p;
}

// The rise of the height over one step, from the samples one step ahead and behind (.r, coverage in .a) and
// `h` between: central where both have data, one-sided where one has, flat where neither has.
float slopeRise(vec4 ahead, float h, vec4 behind) {
  if (ahead.a > 0.0 && behind.a > 0.0) return 0.5 * (ahead.r - behind.r);
  if (ahead.a > 0.0) return ahead.r - h;
  return behind.a > 0.0 ? h - behind.r : 0.0;
}

// The slope's angle, rad (0 flat, pi/2 vertical), of slopes east and north times `exaggeration`.
float slopeAngle(vec2 slopes, float exaggeration) { return atan(exaggeration * length(slopes)); }
