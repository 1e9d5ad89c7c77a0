// Near-side perspective, vertical or tilted (PROJ's nsper and tpers; Snyder 1987, ch. 23), on the sphere of
// radius a: the single-precision form of core/projection/src/perspective.cpp.
#include "strata/constants.glsl"

// Map coordinates of `lonlat` over the horizon's radius; .z is 0 beyond the horizon and behind the camera.
// a = (lon_0, lat_0, h / a, tilt); b = (azimuth, 1 / horizon radius over a, false origin over that radius).
vec3 perspective(vec2 lonlat, vec4 a, vec4 b) {
  float lon = lonlat.x - a.x;
  float height = a.z;
  float sinLat0 = sin(a.y), cosLat0 = cos(a.y), cosLat = cos(lonlat.y);
  float sinHalfLat = sin(0.5 * (lonlat.y - a.y)), sinHalfLon = sin(0.5 * lon);
  // 1 - cos(c) of the angle c from the centre by the haversine: exact near the centre, where low cameras see.
  float versine = 2.0 * (sinHalfLat * sinHalfLat + cosLat * cosLat0 * sinHalfLon * sinHalfLon);
  float k = height / (height + versine);
  float north = sin(lonlat.y - a.y) + 2.0 * sinLat0 * cosLat * sinHalfLon * sinHalfLon;
  vec2 plane = k * vec2(cosLat * sin(lon), north);
  float sinTilt = sin(a.w), cosTilt = cos(a.w), sinAzimuth = sin(b.x), cosAzimuth = cos(b.x);
  float along = plane.y * cosAzimuth + plane.x * sinAzimuth;
  float depth = along * sinTilt / height + cosTilt;
  vec2 photo = vec2((plane.x * cosAzimuth - plane.y * sinAzimuth) * cosTilt, along) / depth;
  float visible = versine <= height / (1.0 + height) && depth > 0.0 ? 1.0 : 0.0;
  return vec3(photo * b.y + b.zw, visible);
}
