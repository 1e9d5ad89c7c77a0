#include "reference_spheres.hpp"

#include <algorithm>
#include <cmath>

#include "cross_section.hpp"

namespace strata::pgm {

double clampPrimaryRadius(double primaryRadius, double eyeDistance) {
  return std::min(primaryRadius, eyeDistance * (1.0 - kLeastAltitudeFraction));
}

// The back-facing hit of the primary tangent ray on the maximum sphere, which is never below the primary
// one: at r_max = r_p, gamma0 is the primary horizon, pi/2 - tau0.
double outermostNormalAngle(double eyeDistance, double primaryRadius, double maximumRadius) {
  return backNormalAngle(eyeDistance, std::max(maximumRadius, primaryRadius), tangentAngle(eyeDistance, primaryRadius));
}

ReferenceSpheres referenceSpheres(double eyeDistance, double primaryRadius, double maximumRadius) {
  const double primary = clampPrimaryRadius(primaryRadius, eyeDistance);
  const double secondary = eyeDistance * std::cos(outermostNormalAngle(eyeDistance, primary, maximumRadius));
  return {primary, std::max(secondary, 0.0)};
}

}  // namespace strata::pgm
