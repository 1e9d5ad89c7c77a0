#version 450 core
// The subdivided, displaced and geomorphed patches (subdivide_patches.comp) turned into eye space.
// Positions arrive relative to the eye, so floats only span what the view sees (docs/architecture.md,
// "Precision"; [Kooima 2008, §3.2.5]); longitude and latitude arrive relative to the point below the eye.
layout(location = 0) in vec4 drawnPoint;           // xyz: m from the eye, planet-fixed axes; w: morph
layout(location = 1) in vec2 lonlatFromReference;  // rad, as drawn
layout(location = 2) in vec4 shadingNormalIn;      // xyz: planet-fixed normal of the displaced surface

uniform mat3 planetToEye;
uniform mat4 projection;

out vec2 vLonlatFromReference;
out vec3 vShadingNormal;

void main() {
  gl_Position = projection * vec4(planetToEye * drawnPoint.xyz, 1.0);
  vLonlatFromReference = lonlatFromReference;
  vShadingNormal = shadingNormalIn.xyz;
}
