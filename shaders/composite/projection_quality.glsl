// composite.projection_quality's weights (seed 000 section 4.1.2, method 2; digest 000 section 5.1), from a
// layer's texel steps to the next sample along the footprint's x (.xy) and y (.zw), in level-0 texels.

// The isotropy of the layer's texels where they land: alpha = 1 - |log k / log n|, k the ratio of the lengths
// of the gradients of the two texture axes (in texels, as the digest advises, so that a 2:1 map's square
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
