#pragma once
// What every built-in projection reads and writes the same way as PROJ: the common terms (+lon_0, +x_0,
// +k_0, ...), the false origin PROJ adds after a projection's own formulas, longitude wrapping, and the
// PROJ text a projection gives back.
#include <numbers>
#include <string>

#include <glm/vec2.hpp>

#include <strata/error.hpp>
#include <strata/plugin/projection.hpp>

namespace strata {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDegree = std::numbers::pi / 180.0;  // radians per degree

// A strata::Error about a projection's terms, from the factories.
Error projectionError(const std::string& problem, const std::string& fix);

// Throws for a figure no projection is defined on (a semi-major axis that is not positive, a flattening
// of one or more).
void checkEllipsoid(const Ellipsoid& ellipsoid);

// Whether map coordinates are plain metres (or degrees) on east/north axes with Greenwich longitudes, as
// the built-in forms compute them; other +units, +to_meter, +axis or +pm are variants they decline.
bool plainFrame(const ProjParameters& terms);

// A latitude term in degrees; throws when outside [-90, 90].
double latitudeTerm(const ProjParameters& terms, const std::string& key, double fallbackDegrees = 0.0);
// The aspect of an azimuthal map centred on latitude `lat0` (degrees): polar where the centre is a pole (to
// 1e-10 rad, PROJ's tolerance for the polar aspects), Other elsewhere.
ProjectionAspect azimuthalAspect(double lat0);
// +k_0 (or its alias +k), 1 when absent; throws unless positive.
double scaleFactorTerm(const ProjParameters& terms);
// The false easting and northing (+x_0, +y_0) in metres.
glm::dvec2 falseOrigin(const ProjParameters& terms);

// Whether `lonlat` (radians) is a place: a finite longitude and a latitude within [-pi/2, pi/2].
bool validLonLat(glm::dvec2 lonlat);
// `lon` moved by whole turns into [centre - pi, centre + pi).
double wrapLongitude(double lon, double centre);

// " +key=value", with the shortest decimal text that reads back as `value`.
std::string term(const std::string& key, double value);
// The figure as PROJ terms: " +R=<a>" for a sphere, " +a=<a> +rf=<1/f>" for an ellipsoid.
std::string ellipsoidTerms(const Ellipsoid& ellipsoid);

}  // namespace strata
