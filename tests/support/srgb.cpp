#include "srgb.hpp"

#include <cmath>

namespace strata::test {

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linearLightOf(int level) { return srgbDecode(level / 255.0); }

}  // namespace strata::test
