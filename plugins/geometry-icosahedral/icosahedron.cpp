#include "icosahedron.hpp"

#include <cmath>
#include <utility>

#include <glm/gtc/constants.hpp>

namespace strata::icosahedral {
namespace {

SphericalTriangle outward(SphericalTriangle t) {
  if (glm::dot(glm::cross(t[1] - t[0], t[2] - t[0]), t[0] + t[1] + t[2]) < 0.0) std::swap(t[1], t[2]);
  return t;
}

}  // namespace

std::vector<SphericalTriangle> icosahedronFaces() {
  const double ringLatitude = std::atan(0.5), step = glm::two_pi<double>() / 5.0;
  auto at = [](double lon, double lat) {
    return glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  };
  // Each vertex is computed once, so that the faces meeting there hold the same bits.
  std::array<glm::dvec3, 5> upper, lower;
  for (int k = 0; k < 5; ++k) upper[k] = at(k * step, ringLatitude), lower[k] = at((k + 0.5) * step, -ringLatitude);
  const glm::dvec3 north(0, 0, 1), south(0, 0, -1);
  std::vector<SphericalTriangle> faces;
  for (int k = 0; k < 5; ++k) {
    const int next = (k + 1) % 5;
    faces.push_back(outward({north, upper[k], upper[next]}));
    faces.push_back(outward({upper[k], lower[k], upper[next]}));
    faces.push_back(outward({upper[next], lower[k], lower[next]}));
    faces.push_back(outward({south, lower[next], lower[k]}));
  }
  return faces;
}

glm::dvec3 greatCircleMidpoint(const glm::dvec3& a, const glm::dvec3& b) { return glm::normalize(a + b); }

}  // namespace strata::icosahedral
