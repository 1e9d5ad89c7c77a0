#version 450 core
#define STRATA_VERTEX_STAGE
STRATA_PROGRAM_DEFINES
// Uniformly subdivided icosahedron, displaced by the height layer, positioned relative to the eye:
// each patch's centre is computed in double on the CPU and arrives here already eye-relative, so the
// float offsets only span one patch (DESIGN.md, Precision; seed 000 section 3.2.5).
#include "strata/surface_point.glsl"

layout(location = 0) in vec3 offsetFromCentre;  // planet-fixed, m, relative to the patch centre
layout(location = 1) in vec3 sphereNormal;      // planet-fixed unit normal
layout(location = 2) in vec2 lonlat;            // rad, unwrapped within the patch

layout(std430, binding = 0) readonly buffer PatchCentres {
  vec4 eyeRelativeCentre[];  // eye space, m
};

uniform mat3 planetToEye;
uniform mat4 projection;
uniform int verticesPerPatch;
uniform float vertexSpacing;  // rad between neighbouring vertices: the height sample's footprint
uniform float radius;         // m, only to turn height differences into slopes

out vec2 vLonlat;
out vec3 vSphereNormal;
out vec3 vShadingNormal;

#ifdef STRATA_HAS_HEIGHT
STRATA_HEIGHT_LAYER_GLSL

float heightAt(vec2 where) {
  SurfacePoint p = SurfacePoint(where, sphereNormal, vec2(vertexSpacing, 0.0), vec2(0.0, vertexSpacing));
  vec4 sampled = STRATA_HEIGHT_FUNCTION(p);
  return sampled.a > 0.0 ? sampled.r : 0.0;  // no height data: the sphere
}

// The displaced surface's normal from central differences of the height over one vertex spacing.
vec3 shadingNormal(float h) {
  float cosLat = max(cos(lonlat.y), 1e-4);
  float dLon = vertexSpacing / cosLat;
  float eastSlope = (heightAt(lonlat + vec2(dLon, 0.0)) - heightAt(lonlat - vec2(dLon, 0.0))) /
                    (2.0 * (radius + h) * vertexSpacing);
  float northSlope = (heightAt(lonlat + vec2(0.0, vertexSpacing)) - heightAt(lonlat - vec2(0.0, vertexSpacing))) /
                     (2.0 * (radius + h) * vertexSpacing);
  vec3 east = vec3(-sin(lonlat.x), cos(lonlat.x), 0.0);
  vec3 north = cross(sphereNormal, east);
  return normalize(sphereNormal - eastSlope * east - northSlope * north);
}
#endif

void main() {
  float h = 0.0;
  vShadingNormal = sphereNormal;
#ifdef STRATA_HAS_HEIGHT
  h = heightAt(lonlat);
  vShadingNormal = shadingNormal(h);
#endif
  int patchIndex = gl_VertexID / verticesPerPatch;  // gl_VertexID includes the draw's base vertex
  vec3 eyePosition = eyeRelativeCentre[patchIndex].xyz + planetToEye * (offsetFromCentre + sphereNormal * h);
  gl_Position = projection * vec4(eyePosition, 1.0);
  vLonlat = lonlat;
  vSphereNormal = sphereNormal;
}
