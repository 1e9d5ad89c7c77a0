// composite.projection_quality's weights ([Kooima 2008, §4.1.2]). Method 2 weighs a layer by its texel steps
// to the next sample along the footprint's x (.xy) and y (.zw), in level-0 texels; method 1 by latitude, from
// the region the layer's projection samples best.

// The isotropy of the layer's texels where they land: alpha = 1 - |log k / log n|, k the ratio of the lengths
// of the gradients of the two texture axes (in texels, which §4.1.2 leaves unsaid, so that a 2:1 map's square
// texels give k = 1), clamped to [0, 1] (it goes negative beyond k = n or 1 / n). 1 without a footprint.
float isotropyWeight(vec4 steps, float n) {
  float alongU = length(steps.xz), alongV = length(steps.yw);
  if (alongU <= 0.0 || alongV <= 0.0) return 1.0;
  return clamp(1.0 - abs(log(alongU / alongV) / log(n)), 0.0, 1.0);
}

// How sharp the layer is there: texels a pixel along its coarser axis, up to 1, beyond which a finer layer is
// no sharper on screen. 1 without a footprint.
float resolutionWeight(vec4 steps) {
  float coarser = min(length(steps.xz), length(steps.yw));
  return coarser > 0.0 ? min(coarser, 1.0) : 1.0;
}

// A layer's weight: its isotropy, times its resolution if asked.
float projectionQualityWeight(vec4 steps, float n, bool resolution) {
  return isotropyWeight(steps, n) * (resolution ? resolutionWeight(steps) : 1.0);
}

// Method 1, "cubic interpolation over distance" ([Kooima 2008, §4.1.2]): the thesis gives no formula, so this
// is a smoothstep (cubic) of latitude across `band` (inner and outer |latitude|, rad; docs/references.md,
// Errata). A map true along the equator counts fully up to the inner latitude and nothing beyond the outer.
float equatorialWeight(float lat, vec2 band) {
  return 1.0 - smoothstep(band.x, band.y, abs(lat));
}

// A polar cap the complement, in its own hemisphere only (`pole`: 1 north, -1 south): in the other, lat * pole
// is negative and the smoothstep 0.
float polarWeight(float lat, float pole, vec2 band) {
  return smoothstep(band.x, band.y, lat * pole);
}
