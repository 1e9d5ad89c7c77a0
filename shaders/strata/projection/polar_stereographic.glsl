// Polar stereographic projection, north or south, sphere or ellipsoid: the single-precision form of
// core/projection/src/polar_stereographic.cpp (Snyder 1987, ch. 21, eqs. 21-33, 21-34 with t of eq. 15-9).
#include "strata/constants.glsl"

// Map coordinates of `lonlat` over a; .z is 0 at the opposite pole, which lies at infinity.
// a = (lon_0, +1 north / -1 south, e, rho / (a t)); b.xy = false origin over a.
vec3 polarStereographic(vec2 lonlat, vec4 a, vec4 b) {
  float lat = a.y * lonlat.y;  // towards the projection's pole
  float sinLat = sin(lat);
  float eSinLat = a.z * sinLat;
  // Snyder's t, with tan(pi/4 - lat/2) as cos(lat) / (1 + sin(lat)): no cancellation near the pole.
  float t = cos(lat) / (1.0 + sinLat) * pow((1.0 + eSinLat) / (1.0 - eSinLat), 0.5 * a.z);
  float rho = a.w * t;
  float lon = lonlat.x - a.x;
  return vec3(vec2(rho * sin(lon), -a.y * rho * cos(lon)) + b.xy, sinLat > -1.0 ? 1.0 : 0.0);
}
