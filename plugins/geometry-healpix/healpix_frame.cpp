#include "healpix_frame.hpp"

#include <cmath>
#include <numbers>

namespace strata::healpix {
namespace {

// +1 for the north faces (0-3), whose cap lies above a = 0; -1 for the south faces (8-11), below it.
double capSide(int face) { return face < 4 ? 1.0 : (face >= 8 ? -1.0 : 0.0); }

// jpll (digest 004 section 1.2): the face's longitude index, phi = (pi / 4) (jpll + c / nr).
int longitudeIndex(int face) {
  constexpr int jpll[12] = {1, 3, 5, 7, 0, 2, 4, 6, 1, 3, 5, 7};
  return jpll[face];
}

}  // namespace

// z and sin(colatitude) as healpix_offset.glsl forms them, here in double: in a cap from the ring number,
// sin = nr sqrt(2/3 - nr^2 / 9), exact to the pole.
HealpixFrame frameAt(const FacePoint& reference) {
  const double side = capSide(reference.face);
  const double a = reference.x + reference.y - 1.0, c = reference.x - reference.y;
  const bool cap = side * a > 0.0;
  const double nr = cap ? 1.0 - side * a : 1.0;
  const double zoneBase = 2.0 / 3.0 * side;
  const double z = zoneBase + (cap ? a * (2.0 - side * a) / 3.0 : 2.0 / 3.0 * a);
  const double sine = cap ? nr * std::sqrt(2.0 / 3.0 - nr * nr / 9.0) : std::sqrt((1.0 - z) * (1.0 + z));
  const double phi = nr > 0.0 ? 0.25 * std::numbers::pi * (longitudeIndex(reference.face) + c / nr) : 0.0;
  return {glm::vec4(float(side), float(a), float(c), float(nr)), glm::vec4(float(z), float(sine), float(phi), 0.0f)};
}

}  // namespace strata::healpix
