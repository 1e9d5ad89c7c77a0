#include "icosphere_mesh.hpp"

#include <array>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace strata::icosahedral {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

// The icosahedron with vertices at both poles (+z north): an upper ring of five at latitude atan(1/2)
// and longitudes 0, 72, ... degrees, a lower ring offset by 36 degrees.
std::vector<Triangle> icosahedronFaces() {
  const double ringLatitude = std::atan(0.5), step = glm::two_pi<double>() / 5.0;
  auto at = [](double lon, double lat) {
    return glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  };
  const glm::dvec3 north(0, 0, 1), south(0, 0, -1);
  std::vector<Triangle> faces;
  for (int k = 0; k < 5; ++k) {
    glm::dvec3 upper = at(k * step, ringLatitude), upperNext = at((k + 1) * step, ringLatitude);
    glm::dvec3 lower = at((k + 0.5) * step, -ringLatitude), lowerNext = at((k + 1.5) * step, -ringLatitude);
    faces.push_back({north, upper, upperNext});
    faces.push_back({upper, lower, upperNext});
    faces.push_back({upperNext, lower, lowerNext});
    faces.push_back({south, lowerNext, lower});
  }
  return faces;
}

// Orders a spherical triangle counter-clockwise seen from outside.
Triangle outward(Triangle t) {
  if (glm::dot(glm::cross(t[1] - t[0], t[2] - t[0]), t[0] + t[1] + t[2]) < 0.0) std::swap(t[1], t[2]);
  return t;
}

// Splits each triangle into four at its edge midpoints (the normalised sum, which is the great-circle
// midpoint, seed 000 section 3.3.3); the sum is symmetric, so shared edges split identically.
std::vector<Triangle> split(const std::vector<Triangle>& triangles) {
  std::vector<Triangle> out;
  for (const Triangle& t : triangles) {
    glm::dvec3 ab = glm::normalize(t[0] + t[1]), bc = glm::normalize(t[1] + t[2]), ca = glm::normalize(t[2] + t[0]);
    out.push_back({t[0], ab, ca});
    out.push_back({ab, t[1], bc});
    out.push_back({ca, bc, t[2]});
    out.push_back({ab, bc, ca});
  }
  return out;
}

double longitudeNear(const glm::dvec3& n, double reference) {
  const double lon = std::atan2(n.y, n.x);
  return reference + std::remainder(lon - reference, glm::two_pi<double>());
}

// Longitude and latitude of each vertex, computed in double from the double normal. Longitude is unwrapped
// around the patch centre, so it interpolates across the antimeridian. A pole has no longitude of its own:
// it takes the mean of the patch's other corners, which lie on the meridians that meet there.
glm::dvec2 lonlatOf(const glm::dvec3& n, const Triangle& patch, double centreLon) {
  const double lat = std::atan2(n.z, std::hypot(n.x, n.y));
  if (std::hypot(n.x, n.y) > 1e-12) return {longitudeNear(n, centreLon), lat};
  double sum = 0.0;
  int count = 0;
  for (const glm::dvec3& corner : patch)
    if (std::hypot(corner.x, corner.y) > 1e-12) sum += longitudeNear(corner, centreLon), ++count;
  return {sum / count, lat};
}

void appendPatch(IcosphereMesh& mesh, const Triangle& patch, double radius, int segments) {
  const glm::dvec3 centreNormal = glm::normalize(patch[0] + patch[1] + patch[2]);
  const glm::dvec3 centre = centreNormal * radius;
  const double centreLon = std::atan2(centreNormal.y, centreNormal.x);
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i <= segments; ++i)
    for (int j = 0; j <= i; ++j) {
      const double wb = double(i - j) / segments, wc = double(j) / segments, wa = 1.0 - double(i) / segments;
      const glm::dvec3 n = glm::normalize(patch[0] * wa + patch[1] * wb + patch[2] * wc);
      mesh.vertices.push_back({glm::vec3(n * radius - centre), glm::vec3(n), glm::vec2(lonlatOf(n, patch, centreLon))});
    }
  auto index = [first](int i, int j) { return first + static_cast<std::uint32_t>(i * (i + 1) / 2 + j); };
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j <= i; ++j) {
      mesh.indices.insert(mesh.indices.end(), {index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      if (j < i) mesh.indices.insert(mesh.indices.end(), {index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  mesh.patchCentres.push_back(centre);
}

}  // namespace

IcosphereMesh buildIcosphereMesh(double radius, int level, int depth) {
  std::vector<Triangle> patches = icosahedronFaces();
  for (int l = 0; l < level; ++l) patches = split(patches);
  const int segments = 1 << depth;
  IcosphereMesh mesh;
  mesh.verticesPerPatch = (segments + 1) * (segments + 2) / 2;
  mesh.vertexSpacing = std::acos(glm::dot(icosahedronFaces()[0][0], icosahedronFaces()[0][1])) / (1 << level) / segments;
  for (const Triangle& patch : patches) appendPatch(mesh, outward(patch), radius, segments);
  return mesh;
}

}  // namespace strata::icosahedral
