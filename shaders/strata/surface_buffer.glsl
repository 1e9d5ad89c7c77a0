// The deferred texturing buffer's one colour attachment (strata/gl/surface_buffer.hpp), written and read
// through these functions alone: longitude and latitude from View::reference (rad) in .xy, kNoSurface's
// longitude where no surface is; where the buffer stores the shading normal (RGBA32F), its octahedral encoding
// plus 2 in .zw ([Cigolle et al. 2014], its "oct" form), so that .z lies in [1, 3]; where the normal is the
// sphere's (RG32F), .zw reads (0, 1).

const float kNoSurface = -1.0e30;  // SurfaceBuffer::kNoSurface

vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

// A unit vector folded onto the octahedron |x| + |y| + |z| = 1 and that onto the square [-1, 1]^2.
vec2 octahedralOf(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * signNotZero(p);
}

vec3 unitVectorOfOctahedral(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
  return normalize(n);
}

// What a surface sample holds: its longitude and latitude from the reference and its shading normal.
vec4 surfaceSample(vec2 lonlatFromReference, vec3 shadingNormal) {
  return vec4(lonlatFromReference, octahedralOf(normalize(shadingNormal)) + 2.0);
}

bool onSurface(vec4 surfaceSample) { return surfaceSample.x > 0.5 * kNoSurface; }

// The shading normal of a sample on the surface whose sphere's normal there is `sphereNormal`: the one stored,
// or the sphere's where the buffer stores none.
vec3 shadingNormalOf(vec4 surfaceSample, vec3 sphereNormal) {
  return surfaceSample.z != 0.0 ? unitVectorOfOctahedral(surfaceSample.zw - 2.0) : sphereNormal;
}

// The sphere's planet-fixed unit normal at longitude/latitude offset `d` from the reference, whose longitude's
// and latitude's sines and cosines `referenceTrig` holds (sin lon, cos lon, sin lat, cos lat), by the
// angle-addition formulas: float keeps the offset's digits, which the sine of an absolute longitude would lose
// (its step is 2.4e-7 rad at 137 degrees: 1.5 m on Earth).
vec3 sphereNormalFromReference(vec2 d, vec4 referenceTrig) {
  float sinLon = referenceTrig.x * cos(d.x) + referenceTrig.y * sin(d.x);
  float cosLon = referenceTrig.y * cos(d.x) - referenceTrig.x * sin(d.x);
  float sinLat = referenceTrig.z * cos(d.y) + referenceTrig.w * sin(d.y);
  float cosLat = referenceTrig.w * cos(d.y) - referenceTrig.z * sin(d.y);
  return vec3(cosLat * cosLon, cosLat * sinLon, sinLat);
}
