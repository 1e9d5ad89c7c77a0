#version 450 core
// geometry.bdam's deferred texturing buffer: each triangle's own normal, from the derivatives of its position across
// the screen (its patches carry no vertex normals: the paper's Mars drew shaded-relief textures), facing outward.
#include "strata/surface_buffer.glsl"

in vec2 vLonlatFromReference;  // rad from View::reference
in vec3 vFromEye;              // m, planet-fixed
in vec3 vOutward;

layout(location = 0) out vec4 surface;

void main() {
  vec3 normal = cross(dFdx(vFromEye), dFdy(vFromEye));
  if (dot(normal, normal) == 0.0) normal = vOutward;
  surface = surfaceSample(vLonlatFromReference, dot(normal, vOutward) < 0.0 ? -normal : normal);
}
