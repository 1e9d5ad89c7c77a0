#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "subdivision_table.hpp"

namespace strata::icosahedral {

// A patch's three corners as the CPU seeds them for the GPU subdivision, in double [Kooima 2008, §3.2.5].
struct PatchSeed {
  std::array<glm::dvec3, 3> normals;    // planet-fixed unit normals of v0, v1, v2 (+z north, +x toward lon 0)
  std::array<glm::dvec2, 3> lonlat;     // rad; longitudes unwrapped, within pi of one another
  std::array<glm::dvec3, 3> positions;  // m, on the sphere, relative to the eye, planet-fixed axes
};

// The seed of the spherical triangle with the given corner normals on the sphere of `radius`, seen from
// `eye` (planet-fixed, m). Longitudes are unwrapped to within pi of `nearLongitude`; a corner at a pole,
// which has no longitude of its own, takes the mean of the other two (the meridians that meet there),
// which the geodesic midpoint then never uses.
PatchSeed patchSeed(const std::array<glm::dvec3, 3>& normals, double radius, const glm::dvec3& eye,
                    double nearLongitude);

// Where longitude and latitude are measured from: a point near the eye, chosen per frame, so that the
// float coordinates of nearby vertices are small numbers with fine resolution. One float ulp of an
// absolute longitude near pi is 1.5 m on Earth ([Kooima 2008, §3.3.4]; docs/references.md, Errata), and of
// an absolute latitude 0.2 to 0.8 m beyond 15 degrees from the equator, so the subdivision measures both
// from the reference.
struct LonLatReference {
  double lon = 0.0;  // rad
  double lat = 0.0;  // rad
};

// One subdivided vertex, in float as the compute pass makes it or in double as its reference.
template <typename Real>
struct GeodesicVertex {
  glm::vec<3, Real> normal;    // planet-fixed unit normal
  Real angle = 0;              // w, rad between the parents' normals; 0 at the corners
  glm::vec<2, Real> lonlat;    // rad, relative to the reference; longitude unwrapped
  glm::vec<3, Real> position;  // m, on the sphere, relative to the eye
};

// The vertices of a patch subdivided as the compute pass does it: level by level through the table, each
// vertex from its two parents alone [Kooima 2008, §3.3.3-3.3.5].
// The seed is taken relative to the reference in double, then rounded to Real. Instantiated for float,
// which mirrors the shader operation for operation, and for double, the reference it is measured by.
template <typename Real>
std::vector<GeodesicVertex<Real>> subdivideGeodesic(const PatchSeed& seed, LonLatReference reference,
                                                    const SubdivisionTable& table);

// The exact surface point of a unit normal, computed directly in double: longitude and latitude by atan2
// (relative to the reference, the longitude unwrapped to within pi of it) and the position as
// radius * normal - eye. Any point's longitude serves at a pole.
struct ExactPoint {
  glm::dvec2 lonlat;    // rad
  glm::dvec3 position;  // m
};
ExactPoint exactSurfacePoint(const glm::dvec3& normal, double radius, const glm::dvec3& eye, LonLatReference reference);

}  // namespace strata::icosahedral
