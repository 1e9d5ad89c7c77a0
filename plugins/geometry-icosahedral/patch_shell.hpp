#pragma once
#include <glm/glm.hpp>
#include <strata/plugin/spherical_cap.hpp>

#include "icosahedron.hpp"

namespace strata::icosahedral {

// The terrain a patch can hold: the wedge of its three great-circle planes between two radii, the
// "surface shell" of [Kooima 2008, §3.2.3]. Everything here is exact for the shell, so culling by it
// never removes terrain that lies inside it.
struct PatchShell {
  SphericalTriangle corners;  // planet-fixed unit normals, counter-clockwise from outside
  double innerRadius;         // m: the body's radius plus the lowest height inside
  double outerRadius;         // m: the body's radius plus the highest height inside
};

// The largest value of dot(direction, u) over the unit vectors u of the spherical triangle: the
// triangle's support function, exact (the direction's nearest point lies inside or on an edge arc).
double largestDot(const SphericalTriangle& triangle, const glm::dvec3& direction);

// The directions whose heights a patch of subdivision `depth` (2^depth segments an edge) samples: the cap
// around its corners widened by two vertex spacings, since a vertex at its edge filters heights over a
// spacing and the filter reads texels of about that size on either side. Its shell takes their heights.
SphericalCap sampledCap(const SphericalTriangle& corners, int depth);

// Whether the unit vector lies inside the spherical triangle (edges included).
bool holds(const SphericalTriangle& triangle, const glm::dvec3& unit);

// Whether every point of the shell is strictly on the negative side of the plane dot(normal, p) + offset = 0.
bool outsidePlane(const PatchShell& shell, const glm::dvec3& normal, double offset);

// Whether the body hides the whole shell from the eye. The body is taken as the sphere of
// `occluderRadius`, below which no terrain lies anywhere; a point at radius R is hidden when its angle
// from the eye's direction exceeds acos(r/d) + acos(r/R): a conservative form of the horizon plane r^2/d of
// [Kooima 2008, §3.2.2], which alone would cull mountains that rise above the horizon (docs/references.md,
// Errata).
bool belowHorizon(const PatchShell& shell, const glm::dvec3& eye, double occluderRadius);

// The least distance of any point of the shell from the eye, m (exact: the nearest point lies in the direction of
// largest dot with the eye's, found by the support function, at the radius nearest the eye's projection on it).
double leastDistance(const PatchShell& shell, const glm::dvec3& eye);

// The face-on distance of a point of the sphere: its distance from the eye over the square root of the
// cosine between its normal and the direction to the eye (at least kGrazingCosine). A small patch there
// subtends the solid angle it would face on at that distance, so splitting by it splits by solid angle as
// [Kooima 2008, §3.2.1] does, while staying a function of each point alone, as geomorphing needs. The
// compute pass computes it per vertex (subdivide_patches.comp).
constexpr double kGrazingCosine = 1.0 / 16.0;  // at the horizon a patch counts as 4 times as far: seen edge on
                                               // it still needs some detail for its silhouette
// The least face-on distance of any point of the shell, its cosine taken to the sphere's normal below it as
// the compute pass takes a displaced vertex's: a bound from below, from the least distance and the largest
// cosine any point can have.
double leastFaceOnDistance(const PatchShell& shell, const glm::dvec3& eye);

}  // namespace strata::icosahedral
