#pragma once
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace strata::procedural {

// Linear RGB in [0, 1] to 8-bit sRGB (IEC 61966-2-1), rounded to the nearest level: how the test data
// store the planet's colours, and how rendered frames are compared with the model.
std::array<std::uint8_t, 3> encodeSrgb8(const glm::dvec3& linear);

}  // namespace strata::procedural
