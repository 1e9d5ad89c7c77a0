#pragma once

namespace strata::pgm {

// The two reference spheres of one view [Mahsman 2010, §3.4]. Both are centred on the planet, so a
// radius is all they need. Lengths are in any one unit.
struct ReferenceSpheres {
  double primary;    // r_p: below the eye, the grid's rays hit it
  double secondary;  // r_s: samples what may rise from beyond the primary horizon; 0 when there is none
};

// The least altitude the eye keeps above the primary sphere, as a fraction of its distance d from the
// centre: 3.4 mm on Mars. At r_p = d every ray would be a tangent.
constexpr double kLeastAltitudeFraction = 1e-9;

// The primary radius kept below the eye, r_p < d, or the cross-section would have no tangent
// ([Mahsman 2010, §3.4] does not say so; docs/references.md, Errata).
double clampPrimaryRadius(double primaryRadius, double eyeDistance);

// gamma0 = pi - asin(r_p/d) - asin(r_p/r_max): where the primary sphere's tangent ray leaves the maximum
// sphere, the largest normal angle any terrain seen above that ray can have ([Mahsman 2010, §3.4.2, Eq. 3.4]).
double outermostNormalAngle(double eyeDistance, double primaryRadius, double maximumRadius);

// Both radii from the eye's distance d, the wanted primary radius and the maximum sphere's radius: the
// primary clamped below d, and r_s = d cos(gamma0) (Eq. 3.6), none (0) where that is not positive, from
// d = r_p / sqrt(1 - (r_p/r_max)^2) outwards (the thesis switches to an impostor there).
ReferenceSpheres referenceSpheres(double eyeDistance, double primaryRadius, double maximumRadius);

}  // namespace strata::pgm
