#pragma once
#include <glm/glm.hpp>

namespace strata::pgm {

// The PGM pass reduces each grid ray to 2D: the plane through the ray and the nadir n (the unit vector
// from the eye to the planet's centre) cuts the spheres in circles [Mahsman 2010, §3.2]. In it the
// ray angle omega lies between the ray and n, and the normal angle gamma between the sphere's normal at
// the hit and the antinadir -n. Angles are in radians, lengths in any one unit, all in double: this is
// the reference the GPU pass will be measured against.

// The constants of one view, the pass's uniforms [Mahsman 2010, §3.6].
struct CrossSection {
  double eyeDistance;       // d: from the eye to the centre
  double primaryRadius;     // r_p, below d (referenceSpheres clamps it)
  double altitude;          // a = d - r_p, the eye's height above the primary sphere
  double primaryTangent;    // tau0 = asin(r_p/d): rays beyond it miss
  double secondaryRadius;   // r_s, 0 when there is no secondary sphere
  double secondaryTangent;  // tau_s = asin(r_s/d)
  double blendStart;        // b = zeta tau0: from here on rays turn towards the secondary sphere
};

// zeta in [0, 1] places the start of the blend, as a fraction of tau0; the thesis's example is 0.9. A
// secondary radius of 0 (none, beyond the distance where it vanishes) leaves the primary sphere alone.
CrossSection crossSection(double eyeDistance, double primaryRadius, double secondaryRadius, double zeta);

// tau = asin(r/d), the angle between the nadir and the rays that graze the sphere of radius r (Eq. 3.5).
double tangentAngle(double eyeDistance, double radius);

// Whether a ray at angle omega from the nadir, given by sin and cos, misses the sphere that the eye is
// the relative altitude a/r above: when (d/r) sin(omega) > 1 [Mahsman 2010, §3.2], or when it points more
// than 90 degrees from the nadir, where omega = asin(r.k) would otherwise alias onto its mirror image
// ([Mahsman 2010, §3.6.3, Eq. 3.9] does not tell them apart).
bool misses(double relativeAltitude, double sinRay, double cosRay);

// The normal angle of the ray's first hit, asin(c u) - asin(u) with c = d/r and u = sin(omega)
// ([Mahsman 2010, §3.6.4, Eqs. 3.3, 3.10]), rewritten so that it loses nothing when c is close to 1, as
// near the ground, where c in float is only a few ulps above 1: with eps = a/r, w = cos(omega) and
// delta = (2 eps + eps^2) u^2 it is asin(u [eps w + delta / (w + sqrt(w^2 - delta))]). For a ray that hits.
double frontNormalAngle(double relativeAltitude, double sinRay, double cosRay);

// The normal angle of the ray's exit from the sphere of radius r: pi - asin((d/r) sin(omega)) - omega
// (Eq. 3.4). For a ray that hits.
double backNormalAngle(double eyeDistance, double radius, double rayAngle);

// How far the ray has turned from the primary towards the secondary sphere: f = (omega - b)/(tau0 - b)
// clamped to [0, 1], 0 up to b and 1 at the tangent. The thesis prints Eq. 3.11 the other way round,
// (omega - tau0)/(b - tau0), against its own text ([Mahsman 2010, §3.6.4, Eq. 3.11];
// docs/references.md, Errata).
double blendFactor(const CrossSection& view, double rayAngle);

// The normal angle on the secondary sphere for blend f: the ray angle omega_s = mix(b, tau_s, f), then
// asin((d/r_s) sin(omega_s)) - omega_s, which is gamma0 at f = 1 [Mahsman 2010, §3.6.4]. Above about
// 387 km on Mars b exceeds tau_s and the asin's argument exceeds 1 near f = 0: it is clamped, where the
// thesis would take the asin of it, a NaN. Needs a secondary sphere.
double secondaryNormalAngle(const CrossSection& view, double blend);

// The normal angle of a ray that hits: mix(gamma_p, gamma_s, f) [Mahsman 2010, §3.6.4].
double normalAngle(const CrossSection& view, double sinRay, double cosRay);

// What the pass writes for one grid ray. A ray that misses the primary sphere, or points away from the
// planet, is replaced by the ray of its cross-section plane that grazes the sphere (omega = tau0): its point
// is the horizon, or beyond it at gamma0 with a secondary sphere, so that the grid's mesh reaches as far as
// the view does (what a miss becomes, [Mahsman 2010, §3.6] leaves unsaid; docs/references.md, Errata).
struct SpherePoint {
  bool hit;             // false: the ray misses; the point is its plane's horizon
  glm::dvec3 normal;    // s, the unit sphere normal
  glm::dvec3 position;  // the point of the primary sphere at normal angle gamma, from the eye
};

// Below this sine of the ray angle the ray is the nadir: gamma = 0. The cross-section plane it would
// span is noise there, but the point it gives lies within 1e-15 a of the nadir point anyway.
constexpr double kNadirSine = 1e-15;

// One grid ray, a unit direction, with the unit nadir in the same frame (planet-fixed or eye space); the
// result is in that frame. The normal is s = -n cos(gamma) + k sin(gamma) (Eq. 3.12), with k the unit
// vector of the plane perpendicular to n on the ray's side. The position is r_p s - d n, written as
// -(a + 2 r_p sin^2(gamma/2)) (-n) + r_p sin(gamma) k so that no large lengths cancel: the thesis's
// t = a sin(rho) / sin(chi) is always a ([Mahsman 2010, §3.6.5]; docs/references.md, Errata).
SpherePoint castRay(const CrossSection& view, const glm::dvec3& ray, const glm::dvec3& nadir);

}  // namespace strata::pgm
