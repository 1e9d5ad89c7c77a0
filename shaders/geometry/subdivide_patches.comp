#version 450 core
// The GPU subdivision of the visible patches (seed 000 section 3.3, done as digest 000 section 3.2 advises
// for GL 4.5): one workgroup per patch fills the breadth-first levels in order, each vertex from its two
// parents in the dependence table, so no ping-pong is needed. The operations mirror
// plugins/geometry-icosahedral/geodesic_subdivision.cpp, whose float form the tests hold to its double one.
layout(local_size_x = 64) in;

struct SeedCorner {
  vec4 position;  // xyz: m on the sphere, relative to the eye, planet-fixed axes; w: unused
  vec4 normal;    // xyz: planet-fixed unit normal
  vec4 lonlat;    // xy: rad from the frame's reference, longitude unwrapped
};

layout(std430, binding = 0) readonly buffer Parents { uvec2 parents[]; };
layout(std430, binding = 1) readonly buffer Seeds { SeedCorner seeds[]; };  // three per patch
layout(std430, binding = 2) restrict buffer Positions { vec4 positions[]; };  // as SeedCorner
layout(std430, binding = 3) restrict buffer Normals { vec4 normals[]; };  // xyz: normal; w: angle to the parents
layout(std430, binding = 4) restrict buffer LonLats { vec2 lonlats[]; };

uniform int depth;
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude

int verticesUpTo(int level) { return ((1 << level) + 1) * ((1 << level) + 2) / 2; }

// The geodesic midpoint of seed 000 section 3.3.4 (digest 000 section 3.4), both coordinates measured
// from the reference: the plain midpoint plus two corrections, second order in the parents' separation,
// so that the GPU's sin, cos and atan (good to about 1e-6 on llvmpipe: tens of metres on Earth in the
// digest's form) only scale small numbers. geodesic_subdivision.cpp derives the form.
vec2 geodesicMidpoint(vec2 j, vec2 k) {
  vec2 middle = 0.5 * (j + k);
  float halfDLon = 0.5 * (k.x - j.x), halfDLat = 0.5 * (k.y - j.y);
  // sin and cos of the absolute mean latitude, from the reference's and the relative one's
  float sinMiddle = referenceLatitude.x * cos(middle.y) + referenceLatitude.y * sin(middle.y);
  float cosMiddle = referenceLatitude.y * cos(middle.y) - referenceLatitude.x * sin(middle.y);
  float cosDelta = cos(halfDLat), sinDelta = sin(halfDLat);
  float cosJ = cosMiddle * cosDelta + sinMiddle * sinDelta, cosK = cosMiddle * cosDelta - sinMiddle * sinDelta;
  float lonCorrection = atan(-sinMiddle * sinDelta * tan(halfDLon), cosMiddle * cosDelta);
  float sinHalfDLon = sin(halfDLon), cosMiddleDelta = cosMiddle * cosDelta;
  float s = cosJ * cosK * sinHalfDLon * sinHalfDLon / (cosMiddleDelta * cosMiddleDelta);
  float root = sqrt(1.0 - s);
  float u = s / (root * (1.0 + root));
  float latCorrection = atan(sinMiddle * cosMiddle * u, 1.0 + u * sinMiddle * sinMiddle);
  return middle + vec2(lonCorrection, latCorrection);
}

void subdivide(uint base, uint i) {
  uvec2 p = parents[i];
  uint j = base + p.x, k = base + p.y;
  vec3 nj = normals[j].xyz, nk = normals[k].xyz;
  // Seed 000 section 3.3.3; the chord keeps w's resolution near 0 where acos would not (digest 000 section 3.3).
  vec3 n = normalize(nj + nk);
  float w = 2.0 * asin(0.5 * length(nj - nk));
  normals[base + i] = vec4(n, w);
  // Ordered by value, so that two patches sharing an edge compute its vertices bit for bit alike.
  vec2 lj = lonlats[j], lk = lonlats[k];
  bool ordered = lj.x < lk.x || (lj.x == lk.x && lj.y <= lk.y);
  lonlats[base + i] = ordered ? geodesicMidpoint(lj, lk) : geodesicMidpoint(lk, lj);
  // Seed 000 section 3.3.5 with the digest's sagitta x tan(w / 4): no radius, so precision follows scale.
  vec4 pj = positions[j], pk = positions[k];
  float halfChord = 0.5 * length(pj.xyz - pk.xyz);
  positions[base + i] = vec4(0.5 * (pj.xyz + pk.xyz) + halfChord * tan(0.25 * w) * n, pj.w);
}

void main() {
  uint patchIndex = gl_WorkGroupID.x, base = patchIndex * uint(verticesUpTo(depth));
  if (gl_LocalInvocationID.x < 3u) {
    SeedCorner corner = seeds[3u * patchIndex + gl_LocalInvocationID.x];
    positions[base + gl_LocalInvocationID.x] = corner.position;
    normals[base + gl_LocalInvocationID.x] = vec4(corner.normal.xyz, 0.0);
    lonlats[base + gl_LocalInvocationID.x] = corner.lonlat.xy;
  }
  memoryBarrierBuffer();
  barrier();
  for (int level = 1; level <= depth; ++level) {
    for (uint i = uint(verticesUpTo(level - 1)) + gl_LocalInvocationID.x; i < uint(verticesUpTo(level)); i += gl_WorkGroupSize.x)
      subdivide(base, i);
    memoryBarrierBuffer();
    barrier();
  }
}
