#include "displaced_patch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace strata::bdam {

DisplacedVertex displacedVertex(double b1, double b2, double metres) {
  const double centimetres = std::round(100.0 * metres);
  if (!(std::abs(centimetres) <= std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("a displacement of " + std::to_string(metres) + " m is beyond +-21,474 km");
  const long second = std::clamp(std::lround(b2 * kBarycentricSteps), 0L, long(kBarycentricSteps));
  const long first = std::clamp(std::lround(b1 * kBarycentricSteps), 0L, kBarycentricSteps - second);
  return {std::uint16_t(first), std::uint16_t(second), std::int32_t(centimetres)};
}

void checkPatch(const DisplacedPatch& patch) {
  for (std::size_t i = 0; i < patch.vertices.size(); ++i)
    if (patch.vertices[i].b1 + patch.vertices[i].b2 > kBarycentricSteps)
      throw std::invalid_argument("vertex " + std::to_string(i) + " lies outside its triangle: b1 + b2 = " +
                                  std::to_string(patch.vertices[i].b1 + patch.vertices[i].b2) + " steps, more than " +
                                  std::to_string(kBarycentricSteps));
  if (patch.indices.size() % 3 != 0)
    throw std::invalid_argument(std::to_string(patch.indices.size()) + " indices are not whole triangles");
  for (std::size_t i = 0; i < patch.indices.size(); ++i)
    if (patch.indices[i] >= patch.vertices.size())
      throw std::invalid_argument("index " + std::to_string(i) + " names vertex " + std::to_string(patch.indices[i]) +
                                  " of " + std::to_string(patch.vertices.size()));
}

}  // namespace strata::bdam
