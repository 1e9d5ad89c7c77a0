#version 450 core
// Per-pixel composition of the surface layers over the deferred texturing buffer (seed 000, section
// 3.4.3): each layer adds value x weight to rgb and its weight to alpha; the sum is normalised at the end
// (section 4.1.2), so overlapping layers blend by coverage and weights need not sum to one.
#include "strata/surface_point.glsl"
#include "strata/constants.glsl"

// vec4 strataDisplay(vec4): scene-linear to the display's encoding, OpenColorIO's code (docs/colour.md).
STRATA_DISPLAY_GLSL

uniform sampler2D surfaceBuffer;
uniform sampler2D shadingBuffer;

uniform vec3 lightDirection;  // planet-fixed, unit, toward the light
uniform float ambient;        // share of light that reaches surfaces facing away
uniform int shade;            // 0: unlit colours, 1: Lambertian
uniform vec3 emptyColour;     // surface where no layer has data (linear)
uniform vec3 background;      // where there is no body (linear)
uniform vec2 referenceLonlat; // rad: View::reference, from which the deferred buffer's lonlat is measured

out vec4 colour;

STRATA_SURFACE_LAYERS_GLSL

// The change of longitude and latitude to the next pixel along `step`, computed from the deferred
// coordinates rather than by dFdx (seed 000, digest section 4.3): the 2 pi jump where patches unwrap
// longitude differently is removed, and at the body's edge the pixel on the other side is used.
vec2 footprint(ivec2 pixel, ivec2 step, vec2 here) {
  vec4 ahead = texelFetch(shadingBuffer, pixel + step, 0);
  vec2 d = ahead.a > 0.0 ? texelFetch(surfaceBuffer, pixel + step, 0).xy - here
                         : here - texelFetch(surfaceBuffer, pixel - step, 0).xy;
  return vec2(d.x - TWO_PI * round(d.x / TWO_PI), d.y);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 shadingSample = texelFetch(shadingBuffer, pixel, 0);
  if (shadingSample.a == 0.0) {
    colour = vec4(strataDisplay(vec4(clamp(background, 0.0, 1.0), 1.0)).rgb, 1.0);
    return;
  }
  vec4 s = texelFetch(surfaceBuffer, pixel, 0);
  vec2 lonlat = referenceLonlat + s.xy;
  float nz = sign(lonlat.y) * sqrt(max(0.0, 1.0 - s.z * s.z - s.w * s.w));  // the sign of z is that of latitude
  SurfacePoint p = SurfacePoint(lonlat, vec3(s.z, s.w, nz), footprint(pixel, ivec2(1, 0), s.xy),
                                footprint(pixel, ivec2(0, 1), s.xy), s.xy);
  vec4 accumulated = vec4(0.0);
  STRATA_SURFACE_LAYERS_ACCUMULATE
  vec3 albedo = accumulated.a > 0.0 ? accumulated.rgb / accumulated.a : emptyColour;
  float light = shade == 1 ? ambient + (1.0 - ambient) * max(dot(normalize(shadingSample.xyz), lightDirection), 0.0) : 1.0;
  colour = vec4(strataDisplay(vec4(clamp(albedo * light, 0.0, 1.0), 1.0)).rgb, 1.0);
}
