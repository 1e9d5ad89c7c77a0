#version 450 core
#define STRATA_GEOMETRY_STAGE
STRATA_PROGRAM_DEFINES
// The displacement pass of projective grid mapping ([Mahsman 2010, §3.7.2, §3.7.1]): each grid point of the
// cast pass (pgm_cast.comp) becomes a vertex of the surface, its point of the primary sphere moved along the
// sphere normal s to the body's radius plus the height there, V = P + (h + R - r_p) s. The height is sampled
// at the point's longitude and latitude from the reference, formed from s in the local east-north-up frame
// (lonlat_from_reference.glsl), over a footprint of the angle to its neighbours in the grid: a level of
// detail from the grid's spacing, where §3.7.1 names none. Everything stays in the local frame, relative to
// the eye.
#include "strata/precise_trig.glsl"
#include "strata/surface_point.glsl"
#include "strata/lonlat_from_reference.glsl"
#include "geometry-pgm/pgm_grid_vertex.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer Normals { vec4 normals[]; };  // the cast pass's
layout(std430, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 2) writeonly buffer Vertices { GridVertex vertices[]; };

uniform ivec2 gridSize;
uniform mat3 localToPlanet;
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude
uniform vec2 referenceLonlat;    // rad: the point below the eye
uniform float radius;            // R, m
uniform float primaryOffset;     // R - r_p, m: from the primary sphere down to the body's radius

#ifdef STRATA_HAS_HEIGHT
STRATA_HEIGHT_LAYER_GLSL
#include "strata/height_sampling.glsl"

// Below this the spacing is taken as this, so that the shading normal's differences never divide by zero
// where neighbours coincide (rays that miss, drawn on the same horizon point). Far below any spacing a grid
// has: 4096 rays across a view 1 cm above the ground are 3e-13 rad apart.
const float kLeastSpacing = 1e-20;

// The largest angle (rad) from the point's sphere normal to its neighbours' in the grid.
float gridSpacing(ivec2 point, vec3 s) {
  float spacing = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 neighbour = point + ivec2(k == 0 ? 1 : (k == 1 ? -1 : 0), k == 2 ? 1 : (k == 3 ? -1 : 0));
    if (any(lessThan(neighbour, ivec2(0))) || any(greaterThanEqual(neighbour, gridSize))) continue;
    spacing = max(spacing, 2.0 * preciseAsin(0.5 * length(normals[neighbour.y * gridSize.x + neighbour.x].xyz - s)));
  }
  return max(spacing, kLeastSpacing);
}
#endif

void main() {
  ivec2 point = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(point, gridSize))) return;
  int i = point.y * gridSize.x + point.x;
  vec3 s = normals[i].xyz, sphereNormal = normalize(localToPlanet * s);
  float h = 0.0;
  vec3 shading = sphereNormal;
#ifdef STRATA_HAS_HEIGHT
  vec2 fromReference = lonlatFromReference(s, referenceLatitude);
  float spacing = gridSpacing(point, s);
  h = heightAndShadingNormal(fromReference, sphereNormal, spacing, shading);
#endif
  vertices[i] = GridVertex(vec4(positions[i].xyz + (h + primaryOffset) * s, h), vec4(s, normals[i].w), vec4(shading, 0.0));
}
