#include "projection/builtin_projections.hpp"

#include "equirectangular.hpp"
#include "healpix.hpp"
#include "orthographic.hpp"
#include "perspective.hpp"
#include "polar_stereographic.hpp"

namespace strata {

std::vector<ProjectionDeclaration> builtinProjections() {
  return {equirectangularDeclaration(), polarStereographicDeclaration(), healpixDeclaration(),
          orthographicDeclaration(), perspectiveDeclaration()};
}

}  // namespace strata
