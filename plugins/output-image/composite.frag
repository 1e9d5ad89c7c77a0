#version 450 core
// Per-pixel composition of the surface layers over the deferred texturing buffer ([Kooima 2008, §3.4.3]): each
// layer adds value x weight to rgb and its weight to alpha; the sum is normalised at the end
// ([Kooima 2008, §4.1.2]), so overlapping layers blend by coverage and weights need not sum to one. Translucent
// surfaces (each a geometry of its own) are then laid over it, farthest first, where they lie nearer, and the
// body's air, where it has one, over all.
#include "strata/surface_point.glsl"
#include "strata/surface_buffer.glsl"
#include "strata/constants.glsl"
#include "strata/local_frame.glsl"

// vec4 strataDisplay(vec4): scene-linear to the display's encoding, OpenColorIO's code (docs/colour.md).
STRATA_DISPLAY_GLSL

// The deferred buffers' sampler: sampler2D, or sampler2DMS where the frame is multisampled (output.image's
// `antialiasing`: STRATA_SAMPLES per pixel); texelFetch's last argument is then the sample, else the level 0.
#define DeferredBuffer STRATA_DEFERRED_SAMPLER
const int kSamples = STRATA_SAMPLES;

uniform DeferredBuffer surfaceBuffer;
uniform DeferredBuffer depthBuffer;

uniform vec3 lightDirection;  // planet-fixed, unit, toward the light (the sun's, where shade is 2)
uniform float ambient;        // share of light that reaches surfaces facing away (by day, where shade is 2)
uniform int shade;            // 0: unlit colours, 1: Lambertian, 2: Lambertian by the sun, dark at night
uniform float twilightSine;   // sine of the sun's depth below the horizon where its light is gone (shade 2)
uniform vec3 emptyColour;     // surface where no layer has data (linear)
uniform vec3 background;      // where there is no body (linear)
uniform vec2 referenceLonlat; // rad: View::reference, from which the deferred buffer's lonlat is measured
uniform vec4 referenceTrig;   // its longitude's and latitude's sines and cosines (sphereNormalFromReference)
uniform ivec2 frameSize;      // pixels, of the frame and the deferred buffers
// 1: the frame is laid over other bodies' (FrameState::transparentBackground): alpha is the share of the pixel's
// samples on the body, its colour their light times that share, plus the air's light beyond the body's edge
// (premultiplied); 0: opaque, the background's samples in it.
uniform int transparentBackground;

out vec4 colour;

// Whether `pixel` lies in the frame: what a fetch beyond it returns is no surface sample.
bool inFrame(ivec2 pixel) { return all(greaterThanEqual(pixel, ivec2(0))) && all(lessThan(pixel, frameSize)); }

// The change of longitude and latitude to the next pixel along `step`, computed from the deferred
// coordinates ([Kooima 2008, §3.4.3]) rather than by the dFdx of §4.1.2: the 2 pi jump where patches unwrap
// longitude differently is removed. Of the pixels ahead and behind, the nearer on the surface is taken: at
// the body's edge or a silhouette the other one lies on the sky or on farther ground. Sample `s` of each.
vec2 footprint(DeferredBuffer surfaces, ivec2 pixel, int s, ivec2 step, vec2 here) {
  vec4 next = texelFetch(surfaces, pixel + step, s), previous = texelFetch(surfaces, pixel - step, s);
  vec2 ahead = next.xy - here, behind = here - previous.xy;
  ahead.x -= TWO_PI * round(ahead.x / TWO_PI);
  behind.x -= TWO_PI * round(behind.x / TWO_PI);
  if (!onSurface(next) || !inFrame(pixel + step)) return behind;
  if (!onSurface(previous) || !inFrame(pixel - step)) return ahead;
  return dot(ahead, ahead) < dot(behind, behind) ? ahead : behind;
}

// The surface point sample `s` of a geometry's surface buffer holds at `pixel`, `here` being that sample.
SurfacePoint surfacePointAt(DeferredBuffer surfaces, ivec2 pixel, int s, vec4 here) {
  return SurfacePoint(referenceLonlat + here.xy, sphereNormalFromReference(here.xy, referenceTrig),
                      footprint(surfaces, pixel, s, ivec2(1, 0), here.xy),
                      footprint(surfaces, pixel, s, ivec2(0, 1), here.xy), here.xy);
}

// How much of the day's light reaches ground of sphere normal `sphereNormal`: 1 where the sun is up, fading
// smoothly to 0 as it sinks through the twilight below the horizon; 1 everywhere unless lit by the sun.
float daylight(vec3 sphereNormal) {
  return shade == 2 ? smoothstep(-twilightSine, 0.0, dot(sphereNormal, lightDirection)) : 1.0;
}

// The light on a surface of shading normal `normal` at sphere normal `sphereNormal`: the ambient share by
// day, and the direct light by Lambert's law.
float lightOn(vec3 normal, vec3 sphereNormal) {
  if (shade == 0) return 1.0;
  return ambient * daylight(sphereNormal) + (1.0 - ambient) * max(dot(normalize(normal), lightDirection), 0.0);
}

STRATA_SURFACE_LAYERS_GLSL

// The body's air (output.image's AirOverSurface): 1 where the body has an atmosphere, else 0.
#if STRATA_ATMOSPHERE
#include "strata/atmosphere.glsl"
uniform vec3 airSun;         // planet-fixed, unit, toward the sun, which lights the air whatever `shade` is
uniform vec3 eyePosition;    // planet-fixed, m (View::eye)
uniform mat3 eyeToPlanet;    // from the eye's axes into planet-fixed ones
uniform vec2 frameTangents;  // View::halfFrameTangents: the frame's edges at unit distance ahead
uniform float nearPlane;     // m: window depth is nearPlane / the distance along the view's axis

// `light` leaving what sample depth `depth` of `pixel` shows (0: nothing, the ray runs on through the air), as it
// reaches the eye: dimmed by the air between, and the air's own light added. The sun's irradiance is 1 as
// Lambert's law takes it here (a white surface under an overhead sun shows 1, pi times its radiance), so the air's
// radiance is shown times pi as well: ground and sky in their true proportion.
vec3 throughAir(ivec2 pixel, vec3 light, float depth) {
  vec3 inEye = vec3(((vec2(pixel) + 0.5) / vec2(frameSize) * 2.0 - 1.0) * frameTangents, -1.0);
  float reach = depth > 0.0 ? nearPlane / depth * length(inEye) : 3.0e38;
  AirLight air = airLightAlong(eyePosition, normalize(eyeToPlanet * inEye), reach, airSun);
  return light * air.transmittance + PI * air.inscattered;
}

// The share of the sun's light that reaches ground of sphere normal `up` (shade 2): reddened low in the sky.
vec3 sunlightThroughAir(vec3 up) { return shade == 2 ? airSunlightOnGround(up, airSun) : vec3(1.0); }
#else
vec3 throughAir(ivec2 pixel, vec3 light, float depth) { return light; }
vec3 sunlightThroughAir(vec3 up) { return vec3(1.0); }
#endif

// The shading normal `normal` at `p` turned by the normal maps' blend `mapped` (value x weight in rgb, the
// weight in alpha; 0 to 1 standing for -1 to 1): x along the east, y the north, z the normal itself.
vec3 mappedNormal(vec3 normal, SurfacePoint p, vec4 mapped) {
  if (mapped.a <= 0.0) return normal;
  vec3 tangent = normalize(mapped.rgb / mapped.a * 2.0 - 1.0);
  return normalize(eastNorthUp(p.lonlat.x, normalize(normal)) * tangent);
}

// vec3 translucentOver(ivec2 pixel, int s, vec3 colour, float depth): the translucent surfaces nearer than
// `depth` at sample `s` laid over `colour` (plugins/output-image/translucent_surfaces.cpp).
STRATA_TRANSLUCENT_GLSL

// The light leaving sample `s` of `pixel`, scene-linear and clamped to what the display shows; in `reach` the
// longer of its footprint's steps (rad), 0 off the body.
vec3 lightAt(ivec2 pixel, int s, out float reach) {
  vec4 here = texelFetch(surfaceBuffer, pixel, s);
  reach = 0.0;
  // Laid over other bodies, off this one only its air shows: its translucent surfaces show where it does.
  if (!onSurface(here)) {
    vec3 behind = transparentBackground == 1 ? background : translucentOver(pixel, s, background, 0.0);
    return clamp(throughAir(pixel, behind, 0.0), 0.0, 1.0);
  }
  SurfacePoint p = surfacePointAt(surfaceBuffer, pixel, s, here);
  reach = max(length(p.lonlatDx), length(p.lonlatDy));
  vec4 accumulated = vec4(0.0), shaded = vec4(0.0);
  STRATA_SURFACE_LAYERS_ACCUMULATE
  float weight = accumulated.a + shaded.a;
  vec3 albedo = weight > 0.0 ? accumulated.rgb / weight : emptyColour;
  vec3 alreadyLit = weight > 0.0 ? shaded.rgb / weight : vec3(0.0);  // layers shaded already: not lit again
  accumulated = vec4(0.0);
  STRATA_NIGHT_LAYERS_ACCUMULATE
  vec3 night = accumulated.a > 0.0 ? accumulated.rgb / accumulated.a : vec3(0.0);
  accumulated = vec4(0.0);
  STRATA_NORMAL_LAYERS_ACCUMULATE
  vec3 normal = mappedNormal(shadingNormalOf(here, p.normal), p, accumulated);
  vec3 light = albedo * lightOn(normal, p.normal) * sunlightThroughAir(p.normal) + alreadyLit +
               night * (1.0 - daylight(p.normal));
  float depth = texelFetch(depthBuffer, pixel, s).r;
  return clamp(throughAir(pixel, translucentOver(pixel, s, light, depth), depth), 0.0, 1.0);
}

// Samples of one surface lie within a pixel's footprint of each other: each holds its triangle's values at
// the pixel's centre, extrapolated where that triangle covers only part of the pixel, which across the edge
// between two triangles of one surface moves them by a small share of a footprint. Across a silhouette
// (nearer ground before farther) they lie farther apart.
const float kSameSurface = 1.0;

// Whether sample `t` of `pixel` shows the surface a sample on the body or off it (`onBody`) shows at `here`
// (its deferred longitude and latitude), within `reach` (rad): both off the body, or both on it lying together.
bool sameSurface(ivec2 pixel, int t, bool onBody, vec2 here, float reach) {
  vec4 there = texelFetch(surfaceBuffer, pixel, t);
  if (onBody != onSurface(there)) return false;
  vec2 apart = there.xy - here;
  apart.x -= TWO_PI * round(apart.x / TWO_PI);
  return !onBody || length(apart) <= reach;
}

// The samples of `pixel` not in `done` (a bit each) that show the surface sample `s` shows, within `reach`.
int samplesLike(ivec2 pixel, int s, float reach, int done) {
  vec4 first = texelFetch(surfaceBuffer, pixel, s);
  bool onBody = onSurface(first);
  vec2 here = first.xy;
  int like = 1 << s;
  for (int t = 0; t < kSamples; ++t)
    if ((done & (1 << t)) == 0 && t != s && sameSurface(pixel, t, onBody, here, reach)) like |= 1 << t;
  return like;
}

// What the pixel's samples off the body add over the bodies behind, `light` being their light times their share
// of the pixel: the air's glow beyond the limb, in the display's encoding, and nothing where there is none.
vec3 offBody(vec3 light) { return any(greaterThan(light, vec3(0.0))) ? strataDisplay(vec4(light, 1.0)).rgb : vec3(0.0); }

// Multisample antialiasing in a deferred frame: the first sample not yet accounted for is composed, and counts
// for every sample showing its surface (within its own footprint); until none is left. The pixel is the mean of
// its samples' light (a box filter in scene-linear light). Inside a surface that is one composition; only
// pixels across the body's edge or a silhouette compose more, and a loop of as many rounds as surfaces costs
// them alone, where a branch per sample would cost every pixel on a SIMD renderer (llvmpipe runs both ways).
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  const int every = (1 << kSamples) - 1;
  vec3 sum = vec3(0.0), onBody = vec3(0.0);
  int done = 0, covered = 0;
  do {
    int s = findLSB(~done & every);
    float reach;
    vec3 light = lightAt(pixel, s, reach);
    int like = samplesLike(pixel, s, kSameSurface * reach, done);
    sum += float(bitCount(like)) * light;
    if (onSurface(texelFetch(surfaceBuffer, pixel, s))) {
      onBody += float(bitCount(like)) * light;
      covered += bitCount(like);
    }
    done |= like;
  } while (done != every);
  if (transparentBackground == 0) {
    colour = vec4(strataDisplay(vec4(sum / float(kSamples), 1.0)).rgb, 1.0);
    return;
  }
  float coverage = float(covered) / float(kSamples);
  vec3 body = covered == 0 ? vec3(0.0) : strataDisplay(vec4(onBody / float(covered), 1.0)).rgb * coverage;
  colour = vec4(body + offBody((sum - onBody) / float(kSamples)), coverage);
}
