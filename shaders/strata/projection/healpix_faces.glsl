// The strip of a HEALPix pyramid (strata/healpix_pyramid.hpp): face + face point x, and face point y, of a
// longitude/latitude, through the planar HEALPix projection (healpix.glsl) and then faceOfPlane of
// core/src/projection/healpix_grid.cpp: on the plane the faces' edge lines are straight, and a face is where
// an ascending and a descending one cross.
#include "strata/projection/healpix.glsl"

// a and b as healpix() takes them (central meridian 0, no false origin).
vec3 healpixFaces(vec2 lonlat, vec4 a, vec4 b) {
  vec2 uv = healpix(lonlat, a, b).xy / (0.25 * PI);
  float ascending = 0.5 * (1.0 + uv.x - uv.y), descending = 0.5 * (1.0 + uv.x + uv.y);
  float ascendingFloor = floor(ascending), descendingFloor = floor(descending);
  // Two apart only by rounding beside a polar triangle's edge: the point is on that edge.
  if (descendingFloor - ascendingFloor > 1.5) descendingFloor -= 1.0;
  if (ascendingFloor - descendingFloor > 1.5) ascendingFloor -= 1.0;
  float face = descendingFloor > ascendingFloor ? mod(ascendingFloor, 4.0)          // north polar
             : ascendingFloor > descendingFloor ? 8.0 + mod(descendingFloor, 4.0)   // south polar
             : 4.0 + mod(ascendingFloor, 4.0);                                      // equatorial
  float x = clamp(descending - descendingFloor, 0.0, 1.0), y = clamp(1.0 - (ascending - ascendingFloor), 0.0, 1.0);
  return vec3(face + x, y, 1.0);
}
