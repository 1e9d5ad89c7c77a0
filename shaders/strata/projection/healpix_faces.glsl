// The strip of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp): face + face point x, and face point y, of a
// longitude/latitude, through the planar HEALPix projection (healpix.glsl) and then faceOfPlane of
// core/projection/src/healpix_grid.cpp: on the plane the faces' edge lines are straight, and a face is where
// an ascending and a descending one cross.
#include "strata/projection/healpix.glsl"

// The greatest face point x a longitude/latitude is mapped to. Face f's x = 1 edge is strip x = f + 1, where
// face f + 1's texels begin (the page cache picks a page by flooring), so points on it are taken 2^-19 of a
// face inside: enough that f + x and the texture coordinate made from it stay below f + 1 in float, for f up
// to 11. Two vertices that share a longitude/latitude share the shift; sampling by face point
// (Layer::faceSamplingFunction), where a vertex on a face edge is a point of either face, keeps to the face's
// pages instead (paged_texture.glsl, pageRange).
const float kHealpixStripLastX = 1.0 - 1.0 / 524288.0;

// a and b as healpix() takes them (central meridian 0, no false origin).
vec3 healpixFaces(vec2 lonlat, vec4 a, vec4 b) {
  vec2 uv = healpix(lonlat, a, b).xy / (0.25 * PI);
  float ascending = 0.5 * (1.0 + uv.x - uv.y), descending = 0.5 * (1.0 + uv.x + uv.y);
  float ascendingFloor = floor(ascending), descendingFloor = floor(descending);
  // Two apart only by rounding beside a polar triangle's edge (or at its apex, the pole): the point is on the
  // edge whose line it lies nearer to, as faceOfPlane has it.
  float aboveAscending = ascending - ascendingFloor, aboveDescending = descending - descendingFloor;
  if (descendingFloor - ascendingFloor > 1.5) {
    if (aboveDescending <= 1.0 - aboveAscending) descendingFloor -= 1.0;
    else ascendingFloor += 1.0;
  } else if (ascendingFloor - descendingFloor > 1.5) {
    if (aboveAscending <= 1.0 - aboveDescending) ascendingFloor -= 1.0;
    else descendingFloor += 1.0;
  }
  float face = descendingFloor > ascendingFloor ? mod(ascendingFloor, 4.0)          // north polar
             : ascendingFloor > descendingFloor ? 8.0 + mod(descendingFloor, 4.0)   // south polar
             : 4.0 + mod(ascendingFloor, 4.0);                                      // equatorial
  float x = clamp(descending - descendingFloor, 0.0, kHealpixStripLastX), y = clamp(1.0 - (ascending - ascendingFloor), 0.0, 1.0);
  return vec3(face + x, y, 1.0);
}
