#version 450 core
// Writes the deferred texturing buffer ([Kooima 2008, §3.4.2]), see strata/gl/surface_buffer.hpp.
in vec2 vLonlatFromReference;  // rad from View::reference
in vec3 vSphereNormal;
in vec3 vShadingNormal;

layout(location = 0) out vec4 surface;  // lon, lat from View::reference; normal x, normal y
layout(location = 1) out vec4 shading;  // shading normal xyz, coverage

void main() {
  vec3 n = normalize(vSphereNormal);
  surface = vec4(vLonlatFromReference, n.x, n.y);
  shading = vec4(normalize(vShadingNormal), 1.0);
}
