#pragma once
// The parameterisations the built-in projections are tested in, and the sampling that the double-precision
// (C++) and single-precision (GLSL) comparisons with PROJ share.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include <strata/plugin/projection.hpp>

#include "proj_reference.hpp"

namespace strata::test {

// Tolerances are stated for a raster this many texels across the projection's full x range.
inline constexpr double kTexelsAcross = 40000.0;

// The IAU spheres of Mars and the Moon, and WGS84.
inline const Ellipsoid kMars{3396190.0, 0.0};
inline const Ellipsoid kMoon{1737400.0, 0.0};
inline const Ellipsoid kWgs84{6378137.0, 298.257223563};

struct ProjectionCase {
  std::string name;   // for test names: letters, digits and underscores
  std::string terms;  // the CRS's PROJ terms, without the figure
  Ellipsoid ellipsoid;
  glm::dvec2 centre;  // longitude and latitude (degrees) at the middle of the compared map window
};

std::vector<ProjectionCase> projectionCases();
// For GoogleTest's messages: the case's name and terms.
void PrintTo(const ProjectionCase& projectionCase, std::ostream* out);
// The case's terms with its figure, as PROJ reads them.
std::string referenceDefinition(const ProjectionCase& projectionCase);
// The built-in projection for the case, through the declarations' create().
std::unique_ptr<Projection> makeProjection(const ProjectionCase& projectionCase);
std::unique_ptr<Projection> makeProjection(const std::string& terms, const Ellipsoid& ellipsoid);

// The window of map coordinates compared: one period by the poles' span for periodic projections, else
// 1.5 times the full x range around the centre. The full x range is the period, the diameter of the
// equator for polar stereographic maps, and that of the visible disc for orthographic and (vertical)
// perspective ones.
struct MapWindow {
  glm::dvec2 min;
  glm::dvec2 max;
  double fullRangeX = 0.0;

  double texel() const { return fullRangeX / kTexelsAcross; }
  bool contains(glm::dvec2 xy) const;
};
MapWindow mapWindow(const ProjectionCase& projectionCase, const Projection& projection, const ProjReference& proj);

// A `count` x `count` grid of cell centres over the window.
std::vector<glm::dvec2> mapSamples(const MapWindow& window, int count);
// Longitudes and latitudes (radians): a global grid of `lonCount` x `latCount` that includes the poles and
// avoids the meridians of the HEALPix seams, latitudes just off the poles and off HEALPix's polar-cap
// boundary, and PROJ's inverse of mapSamples(window, mapCount), dense where the projection is.
std::vector<glm::dvec2> lonlatSamples(const ProjReference& proj, const MapWindow& window, int lonCount, int latCount,
                                      int mapCount);

// Whether forward() changes between defined and empty within `delta` radians of `lonlat`, in any direction:
// the rim of the visible hemisphere, the horizon.
bool nearRim(const Projection& projection, glm::dvec2 lonlat, double delta);
// Whether forward() jumps by more than `jump` within `delta` radians of longitude or latitude: the seams of
// HEALPix's polar triangles, the east/west edge of maps that wrap around the body.
bool nearSeam(const Projection& projection, glm::dvec2 lonlat, double delta, double jump);

// The distance between two map points, across the period for periodic projections.
double mapDistance(const Projection& projection, glm::dvec2 a, glm::dvec2 b);

}  // namespace strata::test
