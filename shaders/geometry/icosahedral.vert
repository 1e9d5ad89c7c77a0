#version 450 core
#define STRATA_VERTEX_STAGE
STRATA_PROGRAM_DEFINES
// The subdivided patches (subdivide_patches.comp), displaced by the height layer and turned into eye
// space. Positions arrive relative to the eye, so floats only span what the view sees (DESIGN.md,
// Precision; seed 000 section 3.2.5); longitude and latitude arrive relative to the point below the eye.
#include "strata/surface_point.glsl"

layout(location = 0) in vec4 eyeRelative;  // xyz: m from the eye to the sphere, planet-fixed axes; w: unused
layout(location = 1) in vec4 sphereNormalIn;  // xyz: planet-fixed unit normal
layout(location = 2) in vec2 lonlatFromReference;  // rad

uniform mat3 planetToEye;
uniform mat4 projection;
uniform vec2 referenceLonlat;  // rad: the point below the eye
uniform float radius;          // m, only to turn height differences into slopes
uniform float footprintPerMetre;  // rad between vertices per metre from the eye (patch_batch.hpp)

out vec2 vLonlatFromReference;
out vec3 vSphereNormal;
out vec3 vShadingNormal;

#ifdef STRATA_HAS_HEIGHT
STRATA_HEIGHT_LAYER_GLSL

// The height at `fromReference` (rad from the point below the eye), sampled over a footprint of one
// vertex spacing.
float heightAt(vec2 fromReference, vec3 normal, float spacing) {
  SurfacePoint p = SurfacePoint(referenceLonlat + fromReference, normal, vec2(spacing, 0.0), vec2(0.0, spacing),
                                fromReference);
  vec4 sampled = STRATA_HEIGHT_FUNCTION(p);
  return sampled.a > 0.0 ? sampled.r : 0.0;  // no height data: the sphere
}

// The displaced surface's normal from central differences of the height over one vertex spacing.
vec3 shadingNormal(float h, vec2 fromReference, vec3 normal, float spacing) {
  vec2 lonlat = referenceLonlat + fromReference;
  float dLon = spacing / max(cos(lonlat.y), 1e-4);
  float eastSlope = (heightAt(fromReference + vec2(dLon, 0.0), normal, spacing) -
                     heightAt(fromReference - vec2(dLon, 0.0), normal, spacing)) / (2.0 * (radius + h) * spacing);
  float northSlope = (heightAt(fromReference + vec2(0.0, spacing), normal, spacing) -
                      heightAt(fromReference - vec2(0.0, spacing), normal, spacing)) / (2.0 * (radius + h) * spacing);
  vec3 east = vec3(-sin(lonlat.x), cos(lonlat.x), 0.0);
  vec3 north = cross(normal, east);
  return normalize(normal - eastSlope * east - northSlope * north);
}
#endif

void main() {
  vec3 sphereNormal = sphereNormalIn.xyz;
  float h = 0.0;
  vShadingNormal = sphereNormal;
#ifdef STRATA_HAS_HEIGHT
  float spacing = footprintPerMetre * length(eyeRelative.xyz);
  h = heightAt(lonlatFromReference, sphereNormal, spacing);
  vShadingNormal = shadingNormal(h, lonlatFromReference, sphereNormal, spacing);
#endif
  vec3 eyePosition = planetToEye * (eyeRelative.xyz + sphereNormal * h);
  gl_Position = projection * vec4(eyePosition, 1.0);
  vLonlatFromReference = lonlatFromReference;
  vSphereNormal = sphereNormal;
}
