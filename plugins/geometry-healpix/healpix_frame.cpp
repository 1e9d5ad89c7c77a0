#include "healpix_frame.hpp"

namespace strata::healpix {

// z, sin(colatitude) and the longitude are strata/plugin/healpix.hpp's; a, c and the ring number are the same
// inverse's terms in the form healpix_offset.glsl takes differences of: the cap lies where side * a > 0,
// and there nr = 1 - |a|.
HealpixFrame frameAt(const FacePoint& reference) {
  const double side = reference.face < 4 ? 1.0 : (reference.face >= 8 ? -1.0 : 0.0);
  const double a = reference.x + reference.y - 1.0, c = reference.x - reference.y;
  const double nr = side * a > 0.0 ? 1.0 - side * a : 1.0;
  const SphericalPoint point = spherical(reference);
  return {glm::vec4(float(side), float(a), float(c), float(nr)),
          glm::vec4(float(point.z), float(point.sinColatitude), float(point.longitude), 0.0f)};
}

}  // namespace strata::healpix
