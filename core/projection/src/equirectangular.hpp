#pragma once
#include <strata/plugin/projection.hpp>

namespace strata {

// Equirectangular: geographic rasters (+proj=longlat, map coordinates in degrees) and PROJ's equidistant
// cylindrical projection (+proj=eqc, in metres).
ProjectionDeclaration equirectangularDeclaration();

}  // namespace strata
