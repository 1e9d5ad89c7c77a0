#version 450 core
// Writes the deferred texturing buffer (strata/gl/surface_buffer.hpp) for projective grid mapping, and each pixel's
// height for the next frame's primary sphere (plugins/geometry-pgm/visible_radius.hpp). Longitude and
// latitude come from the interpolated sphere normal, as [Mahsman 2010, §3.7.2] does (its Fig. 3.52):
// interpolated longitudes would sweep through 180 degrees across a triangle that straddles the meridian
// opposite the reference. Its local-frame form keeps float's precision near the eye.
#include "strata/precise_trig.glsl"
#include "strata/lonlat_from_reference.glsl"
#include "strata/surface_buffer.glsl"

in vec3 vLocalNormal;
in vec3 vShadingNormal;
in float vHeight;

uniform vec2 referenceLatitude;  // sin and cos of the reference latitude

layout(location = 0) out vec4 surface;
layout(location = 1) out float height;  // m above the body's radius

void main() {
  surface = surfaceSample(lonlatFromReference(normalize(vLocalNormal), referenceLatitude), vShadingNormal);
  height = vHeight;
}
