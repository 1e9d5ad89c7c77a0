// HEALPix projection [Calabretta & Roukema 2007], sphere or ellipsoid through the authalic latitude as PROJ
// maps it: the single-precision form of core/projection/src/healpix.cpp.
#include "strata/constants.glsl"

// atanh(u) / u by its Taylor series, for |u| < 0.4 (eccentricities of planets): GLSL's atanh goes through
// log((1 + u) / (1 - u)), which loses the relative precision of small u.
float healpixAtanhRatio(float u) {
  float u2 = u * u;
  return 1.0 + u2 * (1.0 / 3.0 + u2 * (1.0 / 5.0 + u2 * (1.0 / 7.0 + u2 * (1.0 / 9.0 + u2 * (1.0 / 11.0 +
         u2 * (1.0 / 13.0 + u2 * (1.0 / 15.0 + u2 / 17.0)))))));
}

// Map coordinates of `lonlat` over the authalic radius; .z is 1 everywhere.
// a = (lon_0, wrap centre - lon_0, e, q_p); b.xy = false origin over the authalic radius.
vec3 healpix(vec2 lonlat, vec4 a, vec4 b) {
  float lon = lonlat.x - a.x;
  lon -= TWO_PI * floor((lon - a.y + PI) / TWO_PI);  // within half a turn of the raster's centre
  float e = a.z, e2 = e * e, qp = a.w;
  float s = abs(sin(lonlat.y)), c = cos(lonlat.y);
  float oneMinusS = c * c / (1.0 + s);
  // |sin(beta)| = q / q_p, and 1 - |sin(beta)| formed without cancellation, for the square root below.
  float z = (1.0 - e2) * s * (1.0 / (1.0 - e2 * s * s) + healpixAtanhRatio(e * s)) / qp;
  float w = e * oneMinusS / (1.0 - e2 * s);
  float oneMinusZ = oneMinusS * ((1.0 + e2 * s) / (1.0 - e2 * s * s) +
                                 (1.0 - e2) / (1.0 - e2 * s) * healpixAtanhRatio(w)) / qp;
  float north = lonlat.y < 0.0 ? -1.0 : 1.0;
  vec2 plane = vec2(lon, north * 0.375 * PI * z);
  if (z > 2.0 / 3.0) {  // the polar caps' triangles
    float sigma = sqrt(3.0 * oneMinusZ);
    float cap = -0.75 * PI + 0.5 * PI * floor(2.0 * lon / PI + 2.0);
    plane = vec2(cap + (lon - cap) * sigma, north * 0.25 * PI * (2.0 - sigma));
  }
  return vec3(plane + b.xy, 1.0);
}
