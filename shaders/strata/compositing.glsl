// What compositors share: a sample's footprint on the body, widened for a filtered look-up, and "over"
// with coverages (composite.overlay_mask lays an overlay over its base; composite.chroma_fusion its fused
// colour over grey).
#include "strata/surface_point.glsl"

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

// "Over" with coverages, where [Kooima 2008, §4.2] accumulates normally, which would average the overlay
// with its base (docs/references.md, Errata): the overlay's value where it has weight a, the base's, with
// its own coverage, beneath the rest.
vec4 overlayOver(vec4 base, vec4 overlay, float a) {
  float baseShare = base.a * (1.0 - a), coverage = a + baseShare;
  return coverage > 0.0 ? vec4((overlay.rgb * a + base.rgb * baseShare) / coverage, coverage) : vec4(0.0);
}
