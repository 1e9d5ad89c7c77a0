#pragma once
#include <glm/glm.hpp>

// Geodesics of the unit sphere in double precision, for camera paths: the point below the camera moves along
// great circles. Points are planet-fixed unit vectors (strata::unitNormal).
namespace strata::paths {

// The angle (rad) between two unit vectors, accurate near 0 and near pi (atan2 of sine and cosine).
double arcAngle(const glm::dvec3& a, const glm::dvec3& b);
// The point a fraction u of the way along the shorter great-circle arc from a to b (Shoemake 1985).
glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double u);
// The tangent vector at p that points along the great circle toward q, as long as the arc (rad): the
// sphere's logarithm map.
glm::dvec3 logarithm(const glm::dvec3& p, const glm::dvec3& q);
// The point reached from p by going along the tangent vector v for |v| rad: the exponential map.
glm::dvec3 exponential(const glm::dvec3& p, const glm::dvec3& v);
// Whether the great circle through a and b is undefined: they are (nearly) antipodal.
bool antipodal(const glm::dvec3& a, const glm::dvec3& b);

// Longitude in [-180, 180) and latitude (deg) of a unit vector, and back.
glm::dvec2 lonLatDegrees(const glm::dvec3& unit);
glm::dvec3 unitVectorDegrees(double lon, double lat);

}  // namespace strata::paths
