#version 450 core
// Per-pixel composition of the surface layers over the deferred texturing buffer ([Kooima 2008, §3.4.3]): each
// layer adds value x weight to rgb and its weight to alpha; the sum is normalised at the end
// ([Kooima 2008, §4.1.2]), so overlapping layers blend by coverage and weights need not sum to one. Translucent
// surfaces (each a geometry of its own) are then laid over it, farthest first, where they lie nearer.
#include "strata/surface_point.glsl"
#include "strata/constants.glsl"

// vec4 strataDisplay(vec4): scene-linear to the display's encoding, OpenColorIO's code (docs/colour.md).
STRATA_DISPLAY_GLSL

uniform sampler2D surfaceBuffer;
uniform sampler2D shadingBuffer;
uniform sampler2D depthBuffer;

uniform vec3 lightDirection;  // planet-fixed, unit, toward the light
uniform float ambient;        // share of light that reaches surfaces facing away
uniform int shade;            // 0: unlit colours, 1: Lambertian
uniform vec3 emptyColour;     // surface where no layer has data (linear)
uniform vec3 background;      // where there is no body (linear)
uniform vec2 referenceLonlat; // rad: View::reference, from which the deferred buffer's lonlat is measured

out vec4 colour;

// The change of longitude and latitude to the next pixel along `step`, computed from the deferred
// coordinates ([Kooima 2008, §3.4.3]) rather than by the dFdx of §4.1.2: the 2 pi jump where patches unwrap
// longitude differently is removed, and at the body's edge the pixel on the other side is used.
vec2 footprint(sampler2D surfaces, sampler2D shading, ivec2 pixel, ivec2 step, vec2 here) {
  vec4 ahead = texelFetch(shading, pixel + step, 0);
  vec2 d = ahead.a > 0.0 ? texelFetch(surfaces, pixel + step, 0).xy - here
                         : here - texelFetch(surfaces, pixel - step, 0).xy;
  return vec2(d.x - TWO_PI * round(d.x / TWO_PI), d.y);
}

// The surface point a geometry's deferred buffers (`surfaces`, `shading`) hold at `pixel`.
SurfacePoint surfacePointAt(sampler2D surfaces, sampler2D shading, ivec2 pixel) {
  vec4 s = texelFetch(surfaces, pixel, 0);
  vec2 lonlat = referenceLonlat + s.xy;
  float nz = sign(lonlat.y) * sqrt(max(0.0, 1.0 - s.z * s.z - s.w * s.w));  // the sign of z is that of latitude
  return SurfacePoint(lonlat, vec3(s.z, s.w, nz), footprint(surfaces, shading, pixel, ivec2(1, 0), s.xy),
                      footprint(surfaces, shading, pixel, ivec2(0, 1), s.xy), s.xy);
}

// The light on a surface of shading normal `normal`.
float lightOn(vec3 normal) {
  return shade == 1 ? ambient + (1.0 - ambient) * max(dot(normalize(normal), lightDirection), 0.0) : 1.0;
}

STRATA_SURFACE_LAYERS_GLSL

// vec3 translucentOver(ivec2 pixel, vec3 colour, float depth): the translucent surfaces nearer than `depth`
// laid over `colour` (plugins/output-image/translucent_surfaces.cpp).
STRATA_TRANSLUCENT_GLSL

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 shadingSample = texelFetch(shadingBuffer, pixel, 0);
  vec3 lit = background;
  if (shadingSample.a > 0.0) {
    SurfacePoint p = surfacePointAt(surfaceBuffer, shadingBuffer, pixel);
    vec4 accumulated = vec4(0.0);
    STRATA_SURFACE_LAYERS_ACCUMULATE
    vec3 albedo = accumulated.a > 0.0 ? accumulated.rgb / accumulated.a : emptyColour;
    lit = albedo * lightOn(shadingSample.xyz);
  }
  float depth = shadingSample.a > 0.0 ? texelFetch(depthBuffer, pixel, 0).r : 0.0;
  colour = vec4(strataDisplay(vec4(clamp(translucentOver(pixel, lit, depth), 0.0, 1.0), 1.0)).rgb, 1.0);
}
