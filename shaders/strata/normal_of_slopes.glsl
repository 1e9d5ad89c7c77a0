// The displaced surface's normal at height `h` from its slopes east and north (rise per rad along the ground), at
// `lonlat` where the sphere's normal is `normal`. The including program declares `float radius` (m, the body's).
#include "strata/local_frame.glsl"

vec3 normalOfSlopes(float h, vec2 lonlat, vec3 normal, vec2 slopes) {
  mat3 local = eastNorthUp(lonlat.x, normal);
  slopes /= radius + h;
  return normalize(normal - slopes.x * local[0] - slopes.y * local[1]);
}
