#include "local_frame.hpp"

#include <cmath>

namespace strata::pgm {

glm::dmat3 planetToLocal(glm::dvec2 reference) {
  const double sinLon = std::sin(reference.x), cosLon = std::cos(reference.x);
  const double sinLat = std::sin(reference.y), cosLat = std::cos(reference.y);
  const glm::dvec3 east(-sinLon, cosLon, 0.0);
  const glm::dvec3 north(-sinLat * cosLon, -sinLat * sinLon, cosLat);
  const glm::dvec3 up(cosLat * cosLon, cosLat * sinLon, sinLat);
  return glm::transpose(glm::dmat3(east, north, up));
}

}  // namespace strata::pgm
