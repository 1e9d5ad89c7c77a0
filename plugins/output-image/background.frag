#version 450 core
// Where no body shows (body_outline.hpp): the background, through the display transform.

// vec4 strataDisplay(vec4): scene-linear to the display's encoding, OpenColorIO's code (docs/colour.md).
STRATA_DISPLAY_GLSL

uniform vec3 background;  // linear

out vec4 colour;

void main() { colour = vec4(strataDisplay(vec4(background, 1.0)).rgb, 1.0); }
