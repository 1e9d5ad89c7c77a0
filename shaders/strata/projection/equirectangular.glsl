// Equirectangular (plate carree) projection: x is longitude, y is latitude, linearly.
#include "strata/constants.glsl"
#include "strata/surface_point.glsl"

// Texture coordinates of `lonlat` in a raster covering extent = (west, south, east, north) in radians,
// row 0 at the north edge. Longitude is taken modulo 2 pi from the west edge, so extents that cross the
// antimeridian or run beyond +-180 degrees need no special case. .z is 1 inside the extent, 0 outside.
vec3 equirectangularCoordinates(vec2 lonlat, vec4 extent) {
  float u = mod(lonlat.x - extent.x, TWO_PI) / (extent.z - extent.x);
  float v = (extent.w - lonlat.y) / (extent.w - extent.y);
  float inside = (u <= 1.0 && v >= 0.0 && v <= 1.0) ? 1.0 : 0.0;
  return vec3(u, v, inside);
}

// The change of those texture coordinates along a footprint step in lonlat.
vec2 equirectangularGradient(vec2 lonlatStep, vec4 extent) {
  return vec2(lonlatStep.x / (extent.z - extent.x), -lonlatStep.y / (extent.w - extent.y));
}

