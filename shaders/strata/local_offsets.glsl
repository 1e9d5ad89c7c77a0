// A surface point's offset from the frame's reference (View::reference) in the reference's tangent plane:
// east and north on the unit sphere, from its longitude/latitude offsets (SurfacePoint::fromReference),
// computed from small quantities only, so that float keeps them to micrometres on Earth. The CPU side
// inverts it (core/layers/src/local_texture_frame.cpp, lonlatOfTangentOffset). `latitude`: the reference's
// sin and cos.
//   e = cos(lat) sin(dlon)
//   n = cos(lat0) sin(lat) - sin(lat0) cos(lat) cos(dlon) = sin(dlat) + 2 sin(lat0) cos(lat) sin^2(dlon / 2)
vec2 tangentOffset(vec2 d, vec2 latitude) {
  float cosLat = latitude.y * cos(d.y) - latitude.x * sin(d.y);
  float sinHalf = sin(0.5 * d.x);
  return vec2(cosLat * sin(d.x), sin(d.y) + 2.0 * latitude.x * cosLat * sinHalf * sinHalf);
}

// How a step (dlon, dlat) at offset `d` moves the tangent offset: its derivatives.
vec2 tangentStep(vec2 d, vec2 latitude, vec2 step) {
  float cosLat = latitude.y * cos(d.y) - latitude.x * sin(d.y);
  float sinLat = latitude.x * cos(d.y) + latitude.y * sin(d.y);
  float sinHalf = sin(0.5 * d.x);
  mat2 jacobian = mat2(cosLat * cos(d.x), latitude.x * cosLat * sin(d.x),
                       -sinLat * sin(d.x), cos(d.y) - 2.0 * latitude.x * sinLat * sinHalf * sinHalf);
  return jacobian * step;
}
