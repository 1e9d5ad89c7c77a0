#version 450 core
// Projective grid mapping's displaced grid (pgm_displace.comp) turned into eye space, its vertices pulled
// from the grid's buffer by the triangles' indices (grid_mesh.cpp). Points arrive relative to
// the eye in the local frame at the point below it, so a rotation is all that is left ([Mahsman 2010, §3.6.5];
// docs/architecture.md, "Precision").
#include "geometry-pgm/pgm_grid_vertex.glsl"

layout(std430, binding = 0) readonly buffer Vertices { GridVertex vertices[]; };

uniform mat3 localToEye;
uniform mat4 projection;

out vec3 vLocalNormal;  // s, local frame: interpolated, not longitude, which would jump at a meridian
out vec3 vShadingNormal;
out float vHeight;      // m above the body's radius

void main() {
  GridVertex v = vertices[gl_VertexID];
  gl_Position = projection * vec4(localToEye * v.point.xyz, 1.0);
  vLocalNormal = v.normal.xyz;
  vShadingNormal = v.shading.xyz;
  vHeight = v.point.w;
}
