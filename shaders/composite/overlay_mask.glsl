// composite.overlay_mask's pieces ([Kooima 2008, §4.2]).

// A layer's footprint in metres along the body: the longer of the sample's two steps (SurfacePoint).
float footprintMetres(SurfacePoint p, float radius) {
  float c = cos(p.lonlat.y);
  return radius * max(length(vec2(p.lonlatDx.x * c, p.lonlatDx.y)), length(vec2(p.lonlatDy.x * c, p.lonlatDy.y)));
}

// The point `p` with its footprint widened `scale` times: a layer sampled there filters over that many more
// of its texels (its coarser levels: box-filtered averages).
SurfacePoint widenedFootprint(SurfacePoint p, float scale) {
  p.lonlatDx *= scale;
  p.lonlatDy *= scale;
  return p;
}

// A mask layer's weight: its value, clamped to [0, 1] (a 0/1 raster, a rasterised polygon, or soft), times
// its coverage (0 beyond its extent: a mask shows the overlay only where it says so).
float maskWeight(vec4 mask) { return clamp(mask.r, 0.0, 1.0) * mask.a; }

// The overlay's weight from its coverage averaged over half the feather's width: 1 inside, 0.5 about its
// edge, 0 outside, so that 2 c - 1 runs from 0 at the edge to 1 about half the width inside it.
float featheredWeight(float averagedCoverage) { return clamp(2.0 * averagedCoverage - 1.0, 0.0, 1.0); }

// "Over" with coverages, where [Kooima 2008, §4.2] accumulates normally, which would average the overlay
// with its base (docs/references.md, Errata): the overlay's value where it has weight a, the base's, with
// its own coverage, beneath the rest.
vec4 overlayOver(vec4 base, vec4 overlay, float a) {
  float baseShare = base.a * (1.0 - a), coverage = a + baseShare;
  return coverage > 0.0 ? vec4((overlay.rgb * a + base.rgb * baseShare) / coverage, coverage) : vec4(0.0);
}
