// composite.overlay_mask's pieces ([Kooima 2008, §4.2]); the footprint and "over" are strata/compositing.glsl's.
#include "strata/compositing.glsl"

// A mask layer's weight: its value, clamped to [0, 1] (a 0/1 raster, a rasterised polygon, or soft), times
// its coverage (0 beyond its extent: a mask shows the overlay only where it says so).
float maskWeight(vec4 mask) { return clamp(mask.r, 0.0, 1.0) * mask.a; }

// The overlay's weight from its coverage averaged over half the feather's width: 1 inside, 0.5 about its
// edge, 0 outside, so that 2 c - 1 runs from 0 at the edge to 1 about half the width inside it.
float featheredWeight(float averagedCoverage) { return clamp(2.0 * averagedCoverage - 1.0, 0.0, 1.0); }
