// Three-dimensional simplex noise (Perlin 2002, "Improving noise"; Gustavson 2005, "Simplex noise
// demystified"), in float: the same lattice, gradients, hash and kernel as
// plugins/source-procedural/simplex_noise.cpp, whose comments say why each constant is what it is.

const float SIMPLEX_SKEW = 1.0 / 3.0;
const float SIMPLEX_UNSKEW = 1.0 / 6.0;
const float SIMPLEX_KERNEL_RADIUS_SQUARED = 0.5;
const float SIMPLEX_NORMALISATION = 76.0;

const vec3 SIMPLEX_GRADIENTS[12] = vec3[12](vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0),
                                            vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
                                            vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, 1, -1), vec3(0, -1, -1));

// Teschner et al. 2003 primes, then Wellons' lowbias32 finaliser; uint arithmetic wraps as in C++.
uint simplexGradientIndex(ivec3 corner, uint seed) {
  uint h = uint(corner.x) * 73856093u ^ uint(corner.y) * 19349663u ^ uint(corner.z) * 83492791u ^ seed * 2654435761u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h % 12u;
}

float simplexCorner(vec3 offset, ivec3 corner, uint seed) {
  float fade = SIMPLEX_KERNEL_RADIUS_SQUARED - dot(offset, offset);
  if (fade <= 0.0) return 0.0;
  fade *= fade;
  return fade * fade * dot(SIMPLEX_GRADIENTS[simplexGradientIndex(corner, seed)], offset);
}

// The noise at lattice point anchor's position plus `local`: the unskewed position of integer skewed cell
// `anchor`, anchor - (anchor.x + anchor.y + anchor.z) / 6, is taken apart from the point, so that a point
// far from the origin (a planet's surface in lattice units, 2^k R / wavelength) keeps float's digits in its
// small remainder (issue 27; plugins/source-procedural/planet_lattice.cpp finds anchors in double). Skewing
// is linear, so the cell is anchor + the remainder's own cell and the offset within it is the remainder's.
float simplexNoiseFrom(ivec3 anchor, vec3 local, uint seed) {
  vec3 cellOrigin = floor(local + (local.x + local.y + local.z) * SIMPLEX_SKEW);
  ivec3 cell = anchor + ivec3(cellOrigin);
  vec3 offset = local - (cellOrigin - (cellOrigin.x + cellOrigin.y + cellOrigin.z) * SIMPLEX_UNSKEW);
  // The tetrahedron holding the point: step along the axis of the largest offset, then the second largest.
  int xBeatsY = int(offset.x >= offset.y), xBeatsZ = int(offset.x >= offset.z), yBeatsZ = int(offset.y >= offset.z);
  ivec3 rank = ivec3(xBeatsY + xBeatsZ, 1 - xBeatsY + yBeatsZ, 2 - xBeatsZ - yBeatsZ);
  ivec3 first = ivec3(equal(rank, ivec3(2)));
  ivec3 second = ivec3(greaterThanEqual(rank, ivec3(1)));
  float sum = simplexCorner(offset, cell, seed) +
              simplexCorner(offset - vec3(first) + SIMPLEX_UNSKEW, cell + first, seed) +
              simplexCorner(offset - vec3(second) + 2.0 * SIMPLEX_UNSKEW, cell + second, seed) +
              simplexCorner(offset - 1.0 + 3.0 * SIMPLEX_UNSKEW, cell + 1, seed);
  return SIMPLEX_NORMALISATION * sum;
}

float simplexNoise(vec3 point, uint seed) { return simplexNoiseFrom(ivec3(0), point, seed); }
