// Orthographic projection, sphere or ellipsoid (EPSG Guidance Note 7-2, section 3.3.5): the single-precision
// form of core/projection/src/orthographic.cpp.
#include "strata/constants.glsl"

// Map coordinates of `lonlat` over a; .z is 0 on the far side.
// a = (lon_0, sin(lat_0), cos(lat_0), e^2); b = (false origin over a, nu at lat_0 over a, lat_0).
vec3 orthographic(vec2 lonlat, vec4 a, vec4 b) {
  float lon = lonlat.x - a.x;
  float sinLat = sin(lonlat.y), cosLat = cos(lonlat.y);
  float visible = a.y * sinLat + a.z * cosLat * cos(lon) >= 0.0 ? 1.0 : 0.0;
  float nu = inversesqrt(1.0 - a.w * sinLat * sinLat);
  // cos(lat_0) sin(lat) - sin(lat_0) cos(lat) cos(lon) without the cancellation near the centre.
  float halfLonSine = sin(0.5 * lon);
  float north = sin(lonlat.y - b.w) + 2.0 * a.y * cosLat * halfLonSine * halfLonSine;
  vec2 plane = vec2(nu * cosLat * sin(lon), nu * north + a.w * (b.z * a.y - nu * sinLat) * a.z);
  return vec3(plane + b.xy, visible);
}
