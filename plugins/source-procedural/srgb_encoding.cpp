#include "srgb_encoding.hpp"

#include <algorithm>
#include <cmath>

namespace strata::procedural {

std::array<std::uint8_t, 3> encodeSrgb8(const glm::dvec3& linear) {
  std::array<std::uint8_t, 3> encoded{};
  for (int c = 0; c < 3; ++c) {
    const double value = std::clamp(linear[c], 0.0, 1.0);
    const double srgb = value <= 0.0031308 ? 12.92 * value : 1.055 * std::pow(value, 1.0 / 2.4) - 0.055;
    encoded[std::size_t(c)] = std::uint8_t(std::lround(255.0 * srgb));
  }
  return encoded;
}

}  // namespace strata::procedural
