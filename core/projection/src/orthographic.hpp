#pragma once
#include <strata/plugin/projection.hpp>

namespace strata {

// Orthographic: the body as seen from infinitely far above a centre point (PROJ's ortho, sphere and
// ellipsoid), for photographs taken from afar.
ProjectionDeclaration orthographicDeclaration();

}  // namespace strata
