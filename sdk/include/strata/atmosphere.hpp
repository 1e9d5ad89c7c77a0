#pragma once
#include <glm/vec3.hpp>
#include <strata/error.hpp>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The air over a body, as a pipeline's `atmosphere:` declares it: molecules (Rayleigh scattering) and aerosols
// (Mie scattering), each thinning exponentially with height above the body's radius [Bruneton 2008, §2]. Three
// channels: red, green and blue light at 680, 550 and 440 nm. The defaults are the Earth's clear sky as
// [Bruneton 2008, §2] gives it and its published reference implementation sets it (docs/atmosphere.md).
struct Atmosphere {
  double thickness = 60000.0;  // m: Rg = 6360 km to Rt = 6420 km, above which the air scatters nothing visible
  glm::dvec3 rayleighScattering{5.8e-6, 13.5e-6, 33.1e-6};  // 1/m at sea level: why the sky is blue
  double rayleighScaleHeight = 8000.0;                      // m: the molecules' density falls by e every 8 km
  double mieScattering = 4.0e-6;                            // 1/m at sea level: a clear day's haze
  double mieExtinction = 4.0e-6 / 0.9;                      // 1/m: aerosols absorb a tenth of what they meet
  double mieScaleHeight = 1200.0;                           // m: haze stays within the lowest kilometres
  double mieAsymmetry = 0.8;  // Cornette-Shanks g: aerosols scatter mostly forward, the sun's glare
  double groundAlbedo = 0.1;  // the ground's mean reflectance, lighting the air from below
  SourceLocation where{};     // the pipeline's `atmosphere:`, for errors about it
};

// Rayleigh's phase function: the share of scattered light per steradian at cos `nu` of the scattering angle
// [Bruneton 2008, §2].
double rayleighPhase(double nu);
// The Cornette-Shanks phase function of aerosols of asymmetry `g` [Bruneton 2008, §2].
double miePhase(double nu, double g);

// An atmosphere over a sphere of radius `ground`: densities, distances to its boundaries and the optical depth
// of paths through it, in double. A ray is given by the radius `r` (m from the body's centre) where it starts
// and the cosine `mu` of its angle from the zenith there.
class AtmosphereModel {
 public:
  AtmosphereModel(const Atmosphere& air, double ground);

  const Atmosphere& air() const { return air_; }
  double bottom() const { return bottom_; }  // m: the body's radius
  double top() const { return top_; }        // m: the radius where the air ends

  glm::dvec3 rayleighScatteringAt(double r) const;  // 1/m
  double mieScatteringAt(double r) const;           // 1/m
  glm::dvec3 extinctionAt(double r) const;          // 1/m: what is scattered and absorbed
  glm::dvec3 scatteringAt(double r) const;          // 1/m: Rayleigh's and Mie's together

  double distanceToTop(double r, double mu) const;     // to where the ray leaves the air
  double distanceToGround(double r, double mu) const;  // to where it meets the ground; meaningful where it does
  bool meetsGround(double r, double mu) const;
  // Along the ray to the first boundary it meets.
  double distanceToBoundary(double r, double mu) const;

  // The optical depth of the first `length` m of the ray, by the midpoint rule in `steps`.
  glm::dvec3 opticalDepth(double r, double mu, double length, int steps) const;
  // The share of light carried along the ray to the top of the air, by `steps` midpoints; for rays that do not
  // meet the ground (meetsGround), which no light crosses.
  glm::dvec3 transmittanceToTop(double r, double mu, int steps) const;

 private:
  static double density(double altitude, double scaleHeight);
  Atmosphere air_;
  double bottom_, top_;
};

}  // namespace strata
STRATA_EXPORTS_END
