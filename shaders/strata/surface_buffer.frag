#version 450 core
// Writes the deferred texturing buffer ([Kooima 2008, §3.4.2]), see strata/gl/surface_buffer.hpp.
#include "strata/surface_buffer.glsl"

in vec2 vLonlatFromReference;  // rad from View::reference
in vec3 vShadingNormal;

layout(location = 0) out vec4 surface;

void main() { surface = surfaceSample(vLonlatFromReference, vShadingNormal); }
