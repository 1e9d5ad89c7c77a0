#pragma once
#include <algorithm>
#include <glm/glm.hpp>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// The planet or moon a pipeline shows: a sphere of the given mean radius. Planet-fixed coordinates are
// geocentric with +z toward the north pole and +x toward longitude 0 on the equator (PROJ's geocentric
// convention; Kooima 2008 uses +y north, see docs/architecture.md, "Conventions").
struct Body {
  std::string name = "Earth";
  double radius = 6371000.0;  // m; the IUGG mean Earth radius
};

// Where a body stands in a scene of several (`bodies:`): its centre and its planet-fixed axes, both in the scene's
// axes, which are the first body's planet-fixed ones.
struct BodyPlacement {
  glm::dvec3 centre{0.0};  // m
  glm::dmat3 axes{1.0};    // columns: the body's x, y and z axes
};

// Heights above the body's radius (m) that a surface keeps within: culling and reference spheres trust
// them, so terrain outside them may be cut off.
struct HeightRange {
  double lowest = 0.0;
  double highest = 0.0;
};

// The height of `terrain` nearest an eye at `altitude` (m above the radius): the level of the ground the
// level of detail measures distances to (the page cache, the near plane, geometry.healpix's height
// filtering). Measured on the body's
// sphere, a view 2 m above a plateau 3 km high would get the detail of 3 km; measured here it gets that
// of 2 m, and never less than the ground actually there needs.
inline double groundLevelNear(const HeightRange& terrain, double altitude) {
  return std::clamp(altitude, terrain.lowest, terrain.highest);
}

}  // namespace strata
STRATA_EXPORTS_END
