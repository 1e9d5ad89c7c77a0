#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace strata::icosahedral {

// A spherical triangle given by the planet-fixed unit normals of its corners, counter-clockwise seen
// from outside the body.
using SphericalTriangle = std::array<glm::dvec3, 3>;

// The 20 faces of the icosahedron with vertices at both poles (+z north): an upper ring of five at
// latitude atan(1/2) and longitudes 0, 72, ... degrees, a lower ring offset by 36 degrees. Faces that
// share an edge share its corners bit for bit.
std::vector<SphericalTriangle> icosahedronFaces();

// The angle its edges subtend at the centre, rad: atan(2). A patch of level L is nominally this halved
// L times across.
constexpr double kFaceEdgeAngle = 1.1071487177940904;

// The great-circle midpoint of two unit normals: their normalised sum, symmetric in its arguments so
// that the two patches sharing an edge split it identically [Kooima 2008, §3.3.3].
glm::dvec3 greatCircleMidpoint(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace strata::icosahedral
