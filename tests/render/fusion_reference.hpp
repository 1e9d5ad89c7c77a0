#pragma once
#include <array>

#include "srgb.hpp"

namespace strata::test {

// composite.chroma_fusion's arithmetic in double on the CPU, written from the standards rather than from its
// GLSL (plugins/composite-chroma-fusion/opponent_spaces.glsl, chroma_fusion.glsl), to predict what the method itself
// cannot reproduce of an image, apart from rendering. Colours are scene-linear Rec. 709 with a D65 white.
using LinearColour = std::array<double, 3>;

enum class OpponentSpace { Lab, YCbCr };

// Relative luminance: IEC 61966-2-1's Y row.
double relativeLuminance(const LinearColour& colour);

// `colour` with its lightness channel in `space` (CIE 1976 L*, or BT.709 Y' of the sRGB-encoded values) set
// to a grey's of relative luminance `luminance`, shifted as such, its two chroma channels kept.
LinearColour fuse(const LinearColour& colour, double luminance, OpponentSpace space);

}  // namespace strata::test
