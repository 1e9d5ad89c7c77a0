// Equirectangular projection, geographic (+proj=longlat) and PROJ's eqc: the single-precision form of
// core/projection/src/equirectangular.cpp (Snyder 1987, ch. 12, eqs. 12-1 and 12-2).
#include "strata/constants.glsl"

// Map coordinates of `lonlat` over the radius (a, or degrees per radian); .z is 1 everywhere.
// a = (lon_0, wrap centre - lon_0, cos(lat_ts), lat_0); b.xy = false origin over the radius.
vec3 equirectangular(vec2 lonlat, vec4 a, vec4 b) {
  float lon = lonlat.x - a.x;
  lon -= TWO_PI * floor((lon - a.y + PI) / TWO_PI);  // within half a turn of the raster's centre
  return vec3(vec2(a.z * lon, lonlat.y - a.w) + b.xy, 1.0);
}
