#version 450 core
#define STRATA_GEOMETRY_STAGE
STRATA_PROGRAM_DEFINES
// The GPU subdivision of the visible patches ([Kooima 2008, §3.3], into one buffer in dependence order rather
// than by §3.3.2's ping-pong; docs/references.md, Errata): one workgroup per patch fills the breadth-first
// levels in order, each vertex from its two parents in the dependence table, so no ping-pong is needed. The
// operations mirror plugins/geometry-icosahedral/geodesic_subdivision.cpp, whose float form the tests hold to
// its double one. Each vertex is then displaced by the height layer and geomorphed: drawn between its
// parents' drawn midpoint and its own surface point by how far its level's split distance lies beyond it
// (docs/geometry.md, "Geomorphing"), so that patches split and merge without pops.
#include "strata/precise_trig.glsl"
#include "strata/surface_point.glsl"
layout(local_size_x = 64) in;

struct SeedCorner {
  vec4 position;  // xyz: m on the sphere, relative to the eye, planet-fixed axes; w: the patch's level
  vec4 normal;    // xyz: planet-fixed unit normal
  vec4 lonlat;    // xy: rad from the frame's reference, longitude unwrapped
};

layout(std430, binding = 0) readonly buffer Parents { uvec2 parents[]; };
layout(std430, binding = 1) readonly buffer Seeds { SeedCorner seeds[]; };  // three per patch
layout(std430, binding = 2) restrict buffer Positions { vec4 positions[]; };  // as SeedCorner
layout(std430, binding = 3) restrict buffer Normals { vec4 normals[]; };  // xyz: normal; w: angle to the parents
layout(std430, binding = 4) restrict buffer LonLats { vec4 lonlats[]; };  // xy: own, zw: drawn; rad from the reference
layout(std430, binding = 5) restrict buffer Surface { vec4 surface[]; };  // xyz: drawn point, m from the eye; w: morph
layout(std430, binding = 6) restrict buffer Shading { vec4 shadingNormals[]; };  // xyz: drawn shading normal;
                                                                                 // w: the detail scale
layout(std430, binding = 7) readonly buffer Details { float seedDetails[]; };  // patchValues a patch

uniform int depth;
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude
uniform vec2 referenceLonlat;    // rad: the point below the eye
uniform float radius;            // m, only to turn height differences into slopes
uniform float footprintPerMetre;  // rad between vertices per metre of face-on distance at detail 1 (patch_batch.hpp)
uniform float splitDistanceUnit;  // m: a patch of level L splits nearer than this halved L times, times the detail
uniform int latticeLevel;         // the detail field's lattice (detail_field.hpp): its vertices' values are seeded
uniform int patchValues;          // seeded values a patch
uniform float grazingCosine;  // the least cosine a face-on distance counts (patch_shell.hpp's kGrazingCosine)
uniform bool onTerrain;       // face-on distances at the displaced points, else on the sphere (PatchBatch::onTerrain)

// The share of a split distance over which a vertex morphs: from its parents' midpoint where its level's
// split distance lies at the vertex to its own point a third nearer. A vertex of a patch's finest level
// lies between half its split distance and all of it, so it is drawn where it is over the nearer third of
// its range and morphs over the farther; CDLOD (Strugar 2009) morphs over about the same share.
const float kMorphBand = 1.0 / 3.0;

int verticesUpTo(int level) { return ((1 << level) + 1) * ((1 << level) + 2) / 2; }

// The geodesic midpoint of [Kooima 2008, §3.3.4], both coordinates measured from the reference rather than
// absolute (docs/references.md, Errata): the plain midpoint plus two corrections, second order in the
// parents' separation, so that sin, cos and atan only scale small numbers. geodesic_subdivision.cpp derives
// the form. The trigonometry is strata/precise_trig.glsl's: NVIDIA's builtin sin and tan are good only to
// about 4e-7 absolute, wholly wrong for the micro-radian angles here (a 720 m error at a pole on an H100),
// and llvmpipe's asin and atan lose digits for tiny arguments.
vec2 geodesicMidpoint(vec2 j, vec2 k) {
  vec2 middle = 0.5 * (j + k);
  float halfDLon = 0.5 * (k.x - j.x), halfDLat = 0.5 * (k.y - j.y);
  // sin and cos of the absolute mean latitude, from the reference's and the relative one's
  float sinRelative, cosRelative, sinDelta, cosDelta;
  preciseSinCos(middle.y, sinRelative, cosRelative);
  preciseSinCos(halfDLat, sinDelta, cosDelta);
  float sinMiddle = referenceLatitude.x * cosRelative + referenceLatitude.y * sinRelative;
  float cosMiddle = referenceLatitude.y * cosRelative - referenceLatitude.x * sinRelative;
  float cosJ = cosMiddle * cosDelta + sinMiddle * sinDelta, cosK = cosMiddle * cosDelta - sinMiddle * sinDelta;
  float lonCorrection = preciseAtan(-sinMiddle * sinDelta * preciseTan(halfDLon), cosMiddle * cosDelta);
  float sinHalfDLon = preciseSin(halfDLon), cosMiddleDelta = cosMiddle * cosDelta;
  float s = cosJ * cosK * sinHalfDLon * sinHalfDLon / (cosMiddleDelta * cosMiddleDelta);
  float root = sqrt(1.0 - s);
  float u = s / (root * (1.0 + root));
  float latCorrection = preciseAtan(sinMiddle * cosMiddle * u, 1.0 + u * sinMiddle * sinMiddle);
  return middle + vec2(lonCorrection, latCorrection);
}

#ifdef STRATA_HAS_HEIGHT
STRATA_HEIGHT_LAYER_GLSL
#include "strata/height_sampling.glsl"
#endif

// The face-on distance of a point of the sphere (patch_shell.hpp), m.
float faceOnDistance(vec3 fromEye, vec3 normal) {
  float distance = length(fromEye);
  return distance / sqrt(clamp(-dot(fromEye, normal) / distance, grazingCosine, 1.0));
}

// How far a vertex of `globalLevel` (its patch's level plus its level within the patch) at `faceOn`
// distance, where the detail scale is `detail`, has morphed toward its own point: 0 where the split that brought
// it in is just being made, 1 a morph band nearer. Vertices of the faces' own levels never morph: the faces are
// never merged.
float morphOf(int globalLevel, float faceOn, float detail) {
  int splitLevel = globalLevel - depth - 1;  // the level whose split makes the vertex a patch's finest
  if (splitLevel < 0) return 1.0;
  float splitDistance = splitDistanceUnit * detail * exp2(-float(splitLevel));
  return clamp((1.0 - faceOn / splitDistance) / kMorphBand, 0.0, 1.0);
}

// Displaces vertex v by the height layer: its own surface point, longitude and latitude, and shading normal.
// On terrain the heights are filtered over the vertex spacing at the displaced point's face-on distance,
// found from a first height filtered at the sphere's: 2 m above a plateau 3 km high the sphere's would filter
// the heights as seen from 3 km.
void displace(uint v) {
  vec3 position = positions[v].xyz, n = normals[v].xyz;
  vec2 lonlat = lonlats[v].xy;
  float h = 0.0, detail = shadingNormals[v].w;
  vec3 shading = n;
#ifdef STRATA_HAS_HEIGHT
  float footprint = footprintPerMetre / detail;
  float spacing = footprint * faceOnDistance(position, n);
  if (onTerrain) spacing = footprint * faceOnDistance(position + heightAt(lonlat, n, spacing) * n, n);
  h = heightAndShadingNormal(lonlat, n, spacing, shading);
#endif
  surface[v] = vec4(position + h * n, 1.0);
  lonlats[v] = vec4(lonlat, lonlat);
  shadingNormals[v] = vec4(shading, detail);
}

// Morphs displaced vertex v, of `globalLevel`, from the midpoint of its parents' drawn points toward its
// own: drawn = mix(midpoint, own, m), and its longitude, latitude and shading normal alike. The morph follows
// the vertex's face-on distance where the patch tree measures it (at its displaced point on terrain, which
// the tree's distance to the patch's shell bounds from below: patch_shell.hpp), so that a split brings a
// vertex in at morph 0.
void morph(uint v, uint j, uint k, int globalLevel) {
  float m = morphOf(globalLevel, faceOnDistance(onTerrain ? surface[v].xyz : positions[v].xyz, normals[v].xyz),
                    shadingNormals[v].w);
  surface[v].w = m;
  if (m == 1.0) return;
  surface[v].xyz = mix(0.5 * (surface[j].xyz + surface[k].xyz), surface[v].xyz, m);
  lonlats[v].zw = mix(0.5 * (lonlats[j].zw + lonlats[k].zw), lonlats[v].xy, m);
  shadingNormals[v].xyz =
      normalize(mix(normalize(shadingNormals[j].xyz + shadingNormals[k].xyz), shadingNormals[v].xyz, m));
}

// Vertex i of the patch from its parents j and k: its normal, longitude and latitude and position, and its detail
// scale, seeded where it is one of the first `seeded` (the lattice's vertices), else its parents' mean (DetailField).
void subdivide(uint base, uint i, uint firstSeed, uint seeded) {
  uvec2 p = parents[i];
  uint j = base + p.x, k = base + p.y;
  shadingNormals[base + i].w =
      i < seeded ? seedDetails[firstSeed + i] : 0.5 * (shadingNormals[j].w + shadingNormals[k].w);
  vec3 nj = normals[j].xyz, nk = normals[k].xyz;
  // [Kooima 2008, §3.3.3], w from the chord, which keeps its resolution near 0 where acos would not
  // (docs/references.md, Errata).
  vec3 n = normalize(nj + nk);
  float w = 2.0 * preciseAsin(0.5 * length(nj - nk));
  normals[base + i] = vec4(n, w);
  // Ordered by value, so that two patches sharing an edge compute its vertices bit for bit alike.
  vec2 lj = lonlats[j].xy, lk = lonlats[k].xy;
  bool ordered = lj.x < lk.x || (lj.x == lk.x && lj.y <= lk.y);
  lonlats[base + i].xy = ordered ? geodesicMidpoint(lj, lk) : geodesicMidpoint(lk, lj);
  // [Kooima 2008, §3.3.5], its missing Fig. 3.9 read as the sagitta x tan(w / 4) (docs/references.md, Errata):
  // no radius, so precision follows scale.
  vec4 pj = positions[j], pk = positions[k];
  float halfChord = 0.5 * length(pj.xyz - pk.xyz);
  positions[base + i] = vec4(0.5 * (pj.xyz + pk.xyz) + halfChord * preciseTan(0.25 * w) * n, pj.w);
}

// Three sweeps, each a barrier apart: the subdivision level by level, which is cheap; the displacement of
// every vertex at once, which samples the height layer five times a vertex and so keeps all invocations
// busy; then the morphs level by level, each from its parents' finished drawn points. Corners keep their
// own points: they have finished morphing while their patch exists (docs/geometry.md).
void main() {
  uint patchIndex = gl_WorkGroupID.x, base = patchIndex * uint(verticesUpTo(depth));
  int patchLevel = int(seeds[3u * patchIndex].position.w);
  uint detailSeeds = patchIndex * uint(patchValues), seeded = uint(verticesUpTo(max(latticeLevel - patchLevel, 0)));
  if (gl_LocalInvocationID.x < 3u) {
    uint v = base + gl_LocalInvocationID.x;
    SeedCorner corner = seeds[3u * patchIndex + gl_LocalInvocationID.x];
    positions[v] = corner.position;
    normals[v] = vec4(corner.normal.xyz, 0.0);
    lonlats[v] = vec4(corner.lonlat.xy, corner.lonlat.xy);
    shadingNormals[v].w = seedDetails[detailSeeds + gl_LocalInvocationID.x];
  }
  memoryBarrierBuffer();
  barrier();
  for (int level = 1; level <= depth; ++level) {
    for (uint i = uint(verticesUpTo(level - 1)) + gl_LocalInvocationID.x; i < uint(verticesUpTo(level)); i += gl_WorkGroupSize.x)
      subdivide(base, i, detailSeeds, seeded);
    memoryBarrierBuffer();
    barrier();
  }
  for (uint i = gl_LocalInvocationID.x; i < uint(verticesUpTo(depth)); i += gl_WorkGroupSize.x) displace(base + i);
  memoryBarrierBuffer();
  barrier();
  for (int level = 1; level <= depth; ++level) {
    for (uint i = uint(verticesUpTo(level - 1)) + gl_LocalInvocationID.x; i < uint(verticesUpTo(level)); i += gl_WorkGroupSize.x)
      morph(base + i, base + parents[i].x, base + parents[i].y, patchLevel + level);
    memoryBarrierBuffer();
    barrier();
  }
}
