#include <strata/plugin/srgb.hpp>

#include <cmath>

namespace strata {
namespace {

float decoded(double encoded) {
  return float(encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4));
}

}  // namespace

glm::vec3 srgbToSceneLinear(double red, double green, double blue) {
  return {decoded(red), decoded(green), decoded(blue)};
}

}  // namespace strata
