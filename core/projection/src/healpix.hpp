#pragma once
#include <strata/plugin/projection.hpp>

namespace strata {

// HEALPix: the equal-area plane of 12 base patches the HEALPix terrain generator is built on
// ([Westerteiger et al. 2011, §3]), as PROJ's healpix projects it (sphere and ellipsoid).
ProjectionDeclaration healpixDeclaration();

}  // namespace strata
