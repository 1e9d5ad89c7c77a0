#version 450 core
#define STRATA_GEOMETRY_STAGE
STRATA_PROGRAM_DEFINES
// geometry.healpix's nodes drawn from one proxy grid ([Westerteiger et al. 2011, §3.2.4]): each inner vertex
// is its node's centre plus a dyadic offset in the base face, placed by the HEALPix inverse taken relative to
// the centre (healpix_offset.glsl); the centre arrives from the eye and from the frame's reference, made in
// double on the CPU (node_batch.hpp), so the GPU only adds small, precise differences (docs/architecture.md,
// "Precision"). A vertex on the node's outline, which neighbours share, is made whole on the CPU
// (node_batch.hpp's BoundaryVertex), so that both get the same bits. Heights are sampled over a footprint
// that follows the vertex's distance, not its node's level, so that nodes sharing a vertex displace it alike.
#include "strata/constants.glsl"
#include "strata/precise_trig.glsl"
#include "strata/surface_point.glsl"
#include "geometry-healpix/healpix_offset.glsl"
#include "strata/lonlat_from_reference.glsl"

struct HealpixNode {
  HealpixFrame frame;
  vec4 centreFromEye;        // xyz: m, planet-fixed; w: the grid cell's size in face units
  vec4 centreFromReference;  // xyz: unit vector minus View::reference's, east-north-up there; w: its longitude
                             // from the reference
  vec4 centre;               // xyz: unit vector, planet-fixed
  vec4 corner;               // x: face; yz: corner 0's face point
};

struct BoundaryVertex {
  vec4 fromEye;        // xyz: m, planet-fixed
  vec4 fromReference;  // xyz: unit vector minus View::reference's, east-north-up there
  vec4 normal;         // xyz: unit vector, planet-fixed
  vec4 facePoint;      // x: face; yz: face point
};

layout(std430, binding = 0) readonly buffer Nodes { HealpixNode nodes[]; };
layout(std430, binding = 1) readonly buffer Boundary { BoundaryVertex boundary[]; };  // 4 gridCells a node
layout(location = 0) in uint nodeIndex;  // the draw's baseInstance (node_buffers.hpp)

uniform int gridCells;
uniform mat3 planetToEye;
uniform mat4 projection;
uniform mat3 planetToReference;  // planet-fixed to east-north-up at View::reference
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude
uniform vec2 referenceLonlat;    // rad: the point below the eye
uniform float radius;            // m
uniform float footprintPerMetre;  // rad of the sphere between vertices per metre from the eye
uniform float groundLevel;        // m above the radius: the ground nearest the eye (groundLevelNear)

out vec2 vLonlatFromReference;
out vec3 vShadingNormal;

#ifdef STRATA_HAS_HEIGHT
STRATA_HEIGHT_LAYER_GLSL
#include "strata/height_sampling.glsl"
#endif

// The place of an outline vertex in its node's run of boundary vertices, edge by edge from corner e towards
// corner e + 1 (corners 0 to 3 at (0, 0), (N, 0), (N, N), (0, N)); -1 inside.
int boundaryIndex(ivec2 lattice) {
  int n = gridCells;
  if (lattice.y == 0 && lattice.x < n) return lattice.x;
  if (lattice.x == n && lattice.y < n) return n + lattice.y;
  if (lattice.y == n && lattice.x > 0) return 2 * n + (n - lattice.x);
  if (lattice.x == 0 && lattice.y > 0) return 3 * n + (n - lattice.y);
  return -1;
}

void main() {
  HealpixNode node = nodes[nodeIndex];
  ivec2 lattice = ivec2(gl_VertexID % (gridCells + 1), gl_VertexID / (gridCells + 1));
  int onOutline = boundaryIndex(lattice);
  vec3 fromEye, fromReference, normal;
  vec3 facePoint = vec3(node.corner.x, node.corner.yz + vec2(lattice) * node.centreFromEye.w);
  if (onOutline >= 0) {
    BoundaryVertex vertex = boundary[int(nodeIndex) * 4 * gridCells + onOutline];
    fromEye = vertex.fromEye.xyz;
    fromReference = vertex.fromReference.xyz;
    normal = vertex.normal.xyz;
    facePoint = vertex.facePoint.xyz;
  } else {
    vec2 offset = (vec2(lattice) - 0.5 * float(gridCells)) * node.centreFromEye.w;  // exact: dyadic
    vec3 d = healpixOffset(node.frame, offset);
    fromEye = node.centreFromEye.xyz + radius * d;
    fromReference = node.centreFromReference.xyz + planetToReference * d;
    normal = normalize(node.centre.xyz + d);
  }
  vec2 lonlat = lonlatFromReference(vec3(fromReference.xy, 1.0 + fromReference.z), referenceLatitude);
  vec3 shading = normal;
#ifdef STRATA_HAS_HEIGHT
  float spacing = footprintPerMetre * length(fromEye + groundLevel * normal);  // measured on the ground
#ifdef STRATA_HEIGHT_FACE_FUNCTION
  float h = heightAtFacePoint(facePoint, spacing);  // the layer's texels are the faces: no projection
  shading = shadingNormal(h, lonlat, normal, spacing);
#else
  float h = heightAndShadingNormal(lonlat, normal, spacing, shading);
#endif
  fromEye += h * normal;
#endif
  gl_Position = projection * vec4(planetToEye * fromEye, 1.0);
  // Unwrapped to within half a turn of the node's centre, so that no triangle of the node interpolates
  // across the meridian opposite the reference, where the longitude from it jumps by a turn. After the
  // heights, which shared vertices must sample alike.
  vLonlatFromReference = lonlat + vec2(TWO_PI * round((node.centreFromReference.w - lonlat.x) / TWO_PI), 0.0);
  vShadingNormal = shading;
}
