#pragma once
#include <strata/plugin/projection.hpp>

namespace strata {

// Polar stereographic, north or south aspect, with any true-scale latitude: PROJ's stere with
// lat_0 = +-90, and ups.
ProjectionDeclaration polarStereographicDeclaration();

}  // namespace strata
