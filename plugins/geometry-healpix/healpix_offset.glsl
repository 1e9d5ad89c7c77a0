// The HEALPix inverse ([Gorski et al. 2005]) taken relative to a reference point of the same base face, in
// float without losing the offset's digits: the unit vector of the face point reference + (dx, dy) minus the
// reference's own, good to a few float roundings of the difference itself
// (plugins/geometry-healpix/healpix_frame.hpp computes the reference's terms in double; the tests hold this
// to the double inverse of strata/plugin/healpix.hpp). Evaluated directly in float, a vertex would be placed only to
// 6e-8 of the radius, 0.4 m on Earth, and not the same way twice.
//
// A face point (x, y) has s = x + y and c = x - y. With a = s - 1, the face's zones meet at a = 0: the
// north faces (0-3) are equatorial below it and polar cap above, z = 2/3 + (2/3) a or 2/3 + a (2 - a) / 3;
// the south faces (8-11) are cap below, z = -2/3 + a (2 + a) / 3, and equatorial above, -2/3 + (2/3) a; the
// equatorial faces (4-7) are equatorial throughout, z = (2/3) a. The ring number nr is 1 in the equatorial
// zone and 1 - |a| in a cap, and the longitude phi = (pi / 4) (jpll + c / nr). Each difference below is
// written so that it is a product of the offset's own small terms, never the difference of two large ones.

const float kQuarterPi = 0.785398163397448;

struct HealpixFrame {
  vec4 zone;       // x: +1 north face, -1 south face, 0 equatorial face; y: a; z: c; w: nr
  vec4 position;   // x: z; y: rho = sin(colatitude); z: phi (rad); w: unused
};

// z minus the zone boundary's z at a, on a face whose cap lies on `side` of a = 0.
float zoneHeight(float side, float a) {
  if (side * a > 0.0) return a * (2.0 - side * a) / 3.0;  // in the cap
  return 2.0 / 3.0 * a;
}

// z(a + da) - z(a) for ring numbers nr before and after: on one side of the boundary as the product of da
// and a sum, in a cap (nr + nr') / 3, which near a pole, unlike 2 - |a + a'|, keeps its digits; across the
// boundary as the two values, each no larger than da.
float heightChange(float side, float a, float da, float nr, float nrAfter) {
  float b = a + da;
  bool capBefore = side * a > 0.0, capAfter = side * b > 0.0;
  if (capBefore != capAfter) return zoneHeight(side, b) - zoneHeight(side, a);
  if (capBefore) return da * (nr + nrAfter) / 3.0;
  return 2.0 / 3.0 * da;
}

// nr(a + da) - nr(a), alike; across the boundary from how far each side lies in the cap, as 1 - |a| would
// round the small part away.
float ringChange(float side, float a, float da) {
  float b = a + da;
  bool capBefore = side * a > 0.0, capAfter = side * b > 0.0;
  if (capBefore != capAfter) return max(side * a, 0.0) - max(side * b, 0.0);
  return capBefore ? -side * da : 0.0;
}

// sin(colatitude) for z and ring number nr: in a cap nr sqrt(2/3 - nr^2 / 9), which keeps its relative
// precision down to the pole, where 1 - z^2 would cancel.
float colatitudeSine(float side, float a, float z, float nr) {
  if (side * a > 0.0) return nr * sqrt(2.0 / 3.0 - nr * nr / 9.0);
  return sqrt(max((1.0 - z) * (1.0 + z), 0.0));
}

// The unit vector of the face point at (dx, dy) from the frame's reference, minus the reference's (planet-
// fixed axes: +z north, +x at longitude 0).
vec3 healpixOffset(HealpixFrame f, vec2 offset) {
  float side = f.zone.x, a = f.zone.y, c = f.zone.z, nr = f.zone.w;
  float z = f.position.x, rho = f.position.y, phi = f.position.z;
  float da = offset.x + offset.y, dc = offset.x - offset.y;
  float dnr = ringChange(side, a, da), nrAfter = nr + dnr;
  float dz = heightChange(side, a, da, nr, nrAfter);
  // phi' - phi = (pi/4) (c' nr - c nr') / (nr' nr), with c' nr - c nr' = dc nr - c dnr.
  float dphi = nrAfter > 0.0 ? kQuarterPi * (dc * nr - c * dnr) / (nrAfter * nr) : 0.0;  // at a pole any phi
  float zAfter = z + dz;
  float rhoAfter = colatitudeSine(side, a + da, zAfter, nrAfter);
  float drho = -dz * (zAfter + z) / (rhoAfter + rho);  // rho'^2 - rho^2 = z^2 - z'^2
  float sinHalf, cosHalf, sinMiddle, cosMiddle;
  preciseSinCos(0.5 * dphi, sinHalf, cosHalf);
  preciseSinCos(phi + 0.5 * dphi, sinMiddle, cosMiddle);
  float cosAfter = cos(phi + dphi), sinAfter = sin(phi + dphi);
  // rho' cos(phi') - rho cos(phi) = drho cos(phi') + rho (cos(phi') - cos(phi)), and the like for sin.
  return vec3(drho * cosAfter - 2.0 * rho * sinHalf * sinMiddle, drho * sinAfter + 2.0 * rho * sinHalf * cosMiddle, dz);
}
