#version 450 core
// geometry.bdam's patches [Cignoni et al. 2003, §4.2, Fig. 5]: each vertex is two barycentrics and a displacement
// along the corners' interpolated normal, P(b) + h N(b), over a displaced triangle whose corners arrive relative to
// the eye (patch_batch.hpp). A vertex on an edge is formed from that edge's two corners alone, from its
// lexicographically lesser end, as displaced_triangle.cpp forms it in double, so that the patches sharing the edge
// compute the same bits and no crack opens between them.
#include "strata/constants.glsl"
#include "strata/precise_trig.glsl"
#include "strata/lonlat_from_reference.glsl"

struct BdamPatch {
  vec4 corners[3];  // xyz: m from the eye, planet-fixed
  vec4 normals[3];  // xyz: unit, planet-fixed
  vec4 edges[2];    // xyz: P1 - P0, P2 - P0, m
  vec4 centre;      // x: the patch's longitude from the reference
  uvec4 edgeOrder;  // x: bit e: the edge opposite corner e runs from its higher-numbered corner
};

layout(std430, binding = 0) readonly buffer Patches { BdamPatch patches[]; };
layout(location = 0) in uvec2 barycentrics;  // b1, b2 in steps of 1 / 4096
layout(location = 1) in int centimetres;     // h along N(b)
layout(location = 2) in uint patchNumber;    // the draw's baseInstance (patch_buffers.hpp)

uniform mat3 planetToEye;
uniform mat4 projection;
uniform mat3 planetToReference;  // planet-fixed to east-north-up at View::reference
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude
uniform float eyeDistance;       // m: the eye from the body's centre

out vec2 vLonlatFromReference;
out vec3 vFromEye;     // m, planet-fixed: for the faces' normals (bdam_surface.frag)
out vec3 vOutward;     // N(b): which way is up

const float kSteps = 4096.0;

// Corner i plus w times (corner j - corner i) of the patch's corners or normals, from the edge's lesser end; the
// corners themselves at the ends. 1 - w is exact for a lattice point's w.
vec3 alongEdge(vec3 values[3], int i, int j, bool fromJ, float w) {
  if (fromJ) {
    int k = i;
    i = j;
    j = k;
    w = 1.0 - w;
  }
  if (w == 0.0) return values[i];
  if (w == 1.0) return values[j];
  precise vec3 point = values[i] + w * (values[j] - values[i]);
  return point;
}

void main() {
  BdamPatch drawn = patches[patchNumber];
  vec3 corners[3] = vec3[3](drawn.corners[0].xyz, drawn.corners[1].xyz, drawn.corners[2].xyz);
  vec3 normals[3] = vec3[3](drawn.normals[0].xyz, drawn.normals[1].xyz, drawn.normals[2].xyz);
  float b1 = float(barycentrics.x) / kSteps, b2 = float(barycentrics.y) / kSteps;
  uint order = drawn.edgeOrder.x;
  precise vec3 onTriangle, normal;
  if (barycentrics.x == 0u) {
    onTriangle = alongEdge(corners, 0, 2, (order & 2u) != 0u, b2);
    normal = alongEdge(normals, 0, 2, (order & 2u) != 0u, b2);
  } else if (barycentrics.y == 0u) {
    onTriangle = alongEdge(corners, 0, 1, (order & 4u) != 0u, b1);
    normal = alongEdge(normals, 0, 1, (order & 4u) != 0u, b1);
  } else if (barycentrics.x + barycentrics.y == 4096u) {
    onTriangle = alongEdge(corners, 1, 2, (order & 1u) != 0u, b2);
    normal = alongEdge(normals, 1, 2, (order & 1u) != 0u, b2);
  } else {
    onTriangle = corners[0] + b1 * drawn.edges[0].xyz + b2 * drawn.edges[1].xyz;
    normal = normals[0] + b1 * (normals[1] - normals[0]) + b2 * (normals[2] - normals[0]);
  }
  precise vec3 fromEye = onTriangle + (0.01 * float(centimetres)) * normal;
  gl_Position = projection * vec4(planetToEye * fromEye, 1.0);
  vec3 fromCentre = planetToReference * fromEye + vec3(0.0, 0.0, eyeDistance);
  vec2 lonlat = lonlatFromReference(normalize(fromCentre), referenceLatitude);
  // Unwrapped to within half a turn of the patch's centre, so that no triangle interpolates across the meridian
  // opposite the reference, where the longitude from it jumps by a turn.
  vLonlatFromReference = lonlat + vec2(TWO_PI * round((drawn.centre.x - lonlat.x) / TWO_PI), 0.0);
  vFromEye = fromEye;
  vOutward = normal;
}
