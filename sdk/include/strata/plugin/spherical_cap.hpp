#pragma once
#include <span>
#include <strata/export.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// A cap of the unit sphere: the directions within `angle` of `centre`. Geometry generators ask a layer's
// values over one (RegionalValueLayer::valuesWithin) for each patch or node they place, and layers bound their blocks
// of texels by one, so that the two meet by one comparison of angles.
struct SphericalCap {
  glm::dvec3 centre{0.0, 0.0, 1.0};  // planet-fixed unit vector
  double angle = 0.0;                // rad, from 0 to pi: pi is the whole sphere

  // Whether some direction lies in both caps.
  bool meets(const SphericalCap& other) const;
  // The same cap, `angle` wider (at most the whole sphere).
  SphericalCap widened(double by) const;
};

// The planet-fixed unit vector of a longitude and latitude (rad), and back (longitude in [-pi, pi]).
glm::dvec3 directionOf(glm::dvec2 lonlat);
glm::dvec2 lonlatOf(const glm::dvec3& direction);

// The angle between two unit vectors, rad: exact to rounding at every angle (acos of a dot loses half its
// digits below a milliradian, a centimetre on Earth being 1.6e-9 rad).
double angleBetween(const glm::dvec3& a, const glm::dvec3& b);

// A cap holding every one of `directions` (unit vectors): centred on their normalised sum, as wide as the
// farthest of them. It holds their spherical convex hull too (a triangle from its corners) while it is at
// most a hemisphere, which it is for directions within a quarter turn of each other.
SphericalCap capAround(std::span<const glm::dvec3> directions);

// A cap holding both.
SphericalCap joined(const SphericalCap& a, const SphericalCap& b);

}  // namespace strata
STRATA_EXPORTS_END
