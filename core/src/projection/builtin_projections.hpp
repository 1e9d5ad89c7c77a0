#pragma once
#include <vector>

#include <strata/projection.hpp>

namespace strata {

// The projections built into Strata (DESIGN.md "Projections"): equirectangular, polar-stereographic,
// healpix, orthographic and perspective.
std::vector<ProjectionDeclaration> builtinProjections();

}  // namespace strata
