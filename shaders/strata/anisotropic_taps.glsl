// Anisotropic filtering by hand, for the paged atlas (strata/paged_texture.glsl: pages have no mip chain a sampler
// could filter across) and for whole rasters (strata/surface_point.glsl: llvmpipe's own anisotropic filtering
// gave white quads). Trilinear filtering ([Kooima 2008, §4.3.2]) blurs a footprint longer one way than the
// other (a view grazing the surface, a map stretched toward its poles) to its longer axis; instead, taps spread
// evenly along the footprint's major axis, each a trilinear sample as wide as the minor axis, or as the major
// axis's share where the footprint is more than kAnisotropicTaps times longer than wide, and the sample is
// their mean.

const int kAnisotropicTaps = 8;  // at most: hardware anisotropic filtering's usual most, 8x

struct AnisotropicTaps {
  vec2 major;   // the footprint's major axis: the taps lie along it, from -major/2 to +major/2
  int count;    // 1 to kAnisotropicTaps
  float width;  // of each tap's trilinear filter
};

// The taps over the footprint whose steps to the next sample are `stepX` and `stepY` (texels), whose ellipse gives
// the axes: the major the longer step, the minor the ellipse's area over it (two long steps nearly alike make a
// long, narrow footprint), but at least a texel: no tap filters finer than the finest level's texels, so taps
// closer together than one sample the same texels. A magnified footprint (the view close to a raster, however
// tilted) takes one tap, a bilinear sample, as hardware filtering does.
AnisotropicTaps anisotropicTaps(vec2 stepX, vec2 stepY) {
  vec2 major = dot(stepX, stepX) > dot(stepY, stepY) ? stepX : stepY;
  float majorLength = length(major);
  float minorLength = max(abs(stepX.x * stepY.y - stepX.y * stepY.x) / max(majorLength, 1e-30), 1.0);
  // Rounded: a footprint up to half again as long as wide takes one tap (trilinear at its major axis, as
  // hardware filtering does), so that a mildly stretched map or a slightly tilted view costs no more.
  int count = int(clamp(round(majorLength / minorLength), 1.0, float(kAnisotropicTaps)));
  return AnisotropicTaps(major, count, max(minorLength, majorLength / float(count)));
}

// Where tap `tap` of `taps` lies from the footprint's centre.
vec2 tapOffset(AnisotropicTaps taps, int tap) { return taps.major * ((float(tap) + 0.5) / float(taps.count) - 0.5); }
