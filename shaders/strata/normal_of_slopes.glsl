// The displaced surface's normal at height `h` from its slopes east and north (rise per rad along the ground), at
// `lonlat` where the sphere's normal is `normal`. The including program declares `float radius` (m, the body's).
vec3 normalOfSlopes(float h, vec2 lonlat, vec3 normal, vec2 slopes) {
  vec3 east = vec3(-sin(lonlat.x), cos(lonlat.x), 0.0);
  vec3 north = cross(normal, east);
  slopes /= radius + h;
  return normalize(normal - slopes.x * east - slopes.y * north);
}
