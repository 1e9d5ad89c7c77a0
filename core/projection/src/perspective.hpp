#pragma once
#include <strata/plugin/projection.hpp>

namespace strata {

// Perspective: a photograph draped from a camera pose, PROJ's vertical (nsper) and tilted (tpers)
// near-side perspective projections.
ProjectionDeclaration perspectiveDeclaration();

}  // namespace strata
