// composite.chroma_fusion's pieces: high-resolution luminance, low-resolution chroma ([Kooima 2008, §1.1],
// HiRISE luminance with Viking chroma, and [Kooima 2008, §3.4.3], colour-space transformations).
#include "composite-chroma-fusion/opponent_spaces.glsl"
#include "strata/compositing.glsl"

// The relative luminance the fused colour takes where the colour layer's is `colour`, the luminance layer's
// `pan` and its low-pass at the colour layer's resolution `panLowpass`. Matching 0 (none): the pan's own.
// Matching 1 (detail): the colour's, times the pan's detail as a ratio to its low-pass (high-pass modulation,
// Liu 2000, "Smoothing Filter-based Intensity Modulation"), which a gain between the two data sets (exposure,
// calibration, illumination) cancels from, so the colour layer keeps its brightness.
float fusedLuminance(float colour, float pan, float panLowpass, int matching) {
  if (matching == 0) return max(pan, 0.0);
  return colour * max(pan, 0.0) / max(panLowpass, 1e-6);
}

// `colour` (scene-linear) with its lightness channel in `space` moved `strength` of the way to that of
// relative luminance `luminance`, its chroma channels kept. The shift is measured between greys of the two
// luminances, so where they agree the colour is untouched in either space (a Y'CbCr colour's luma is not
// its luminance's encoding).
vec3 chromaFusion(vec3 colour, float luminance, float strength, int space) {
  vec3 opponent = toOpponent(colour, space);
  float own = dot(colour, REC709_LUMINANCE);
  opponent.x += strength * (opponentLightness(luminance, space) - opponentLightness(own, space));
  return fromOpponent(opponent, space);
}

// The footprint scale at which a layer filters over one texel of the colour layer, whose texel steps there
// are `colourSteps` (texelStepsFunction): at least 1, as a footprint already wider has nothing finer to drop.
float colourTexelScale(vec4 colourSteps) {
  return max(1.0 / max(max(length(colourSteps.xy), length(colourSteps.zw)), 1e-6), 1.0);
}
