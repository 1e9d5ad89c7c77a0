#pragma once

namespace strata::test {

// IEC 61966-2-1's sRGB transfer function and its inverse, in double: how the tests read the display-encoded
// frames output.image writes back into linear light, and encode what they expect.
double srgbEncode(double linear);
double srgbDecode(double encoded);

// An 8-bit sRGB level (0 to 255) in linear light.
double linearLightOf(int level);

}  // namespace strata::test
