// Longitude and latitude from the reference (View::reference, the point below the eye) of a unit vector s
// given in the east-north-up frame there (strata/camera.hpp's planetToLocal), without cancellation, so
// that float resolves them near the eye as finely as s's small east and north components. Latitude
// phi0 is the reference's, given as sin and cos.
//
// Turned into the reference's meridian plane, s has the horizontal component x' = cos(phi0) s_up -
// sin(phi0) s_north along the meridian and y' = s_east across it, so the longitude from the reference is
// atan(y', x'). With rho = sqrt(x'^2 + y'^2) = cos(phi), sin(phi - phi0) = cos(phi0) sin(phi) - sin(phi0)
// rho; writing rho = x' + y'^2 / (rho + x') the terms in s_up cancel exactly, leaving
// sin(phi - phi0) = s_north - sin(phi0) y'^2 / (rho + x'). Beyond the pole, where x' < 0, rho + x' loses
// its digits and rho - x' is the same term.
vec2 lonlatFromReference(vec3 s, vec2 referenceLatitude) {
  float sinLat0 = referenceLatitude.x, cosLat0 = referenceLatitude.y;
  float along = cosLat0 * s.z - sinLat0 * s.y, across = s.x;
  float rho = sqrt(along * along + across * across);
  float beyond = along >= 0.0 ? across * across / max(rho + along, 1e-30) : rho - along;
  float sinDLat = s.y - sinLat0 * beyond;
  float cosDLat = rho * cosLat0 + (sinLat0 * s.z + cosLat0 * s.y) * sinLat0;
  return vec2(preciseAtan(across, along), preciseAtan(sinDLat, cosDLat));
}
