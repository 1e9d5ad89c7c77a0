#pragma once
#include <glm/vec3.hpp>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// A colour a pipeline gives as numbers (a relief's tint ramp, a peel's cut faces): red, green and blue
// sRGB-encoded in [0, 1], as colour pickers and web colours give them, decoded by IEC 61966-2-1 to the
// linear Rec. 709 light Strata composes in (Strata's OpenColorIO config's `srgb` to `linear`,
// docs/colour.md).
glm::vec3 srgbToSceneLinear(double red, double green, double blue);

}  // namespace strata
STRATA_EXPORTS_END
