#pragma once
#include <glm/glm.hpp>

#include <strata/plugin/healpix.hpp>

namespace strata::healpix {

// The terms of a reference point of a base face that plugins/geometry-healpix/healpix_offset.glsl takes unit
// vectors relative to, computed in double and laid out as its std430 struct HealpixFrame. With s = x + y
// and c = x - y of the face point, a = s - 1 is 0 where the face's equatorial zone meets its polar cap.
struct HealpixFrame {
  glm::vec4 zone;  // x: +1 north face, -1 south face, 0 equatorial face; y: a; z: c; w: ring number nr
  glm::vec4
      position;  // x: z; y: sin(colatitude); z: longitude phi (rad), as strata/plugin/healpix.hpp's spherical; w: 0
};

HealpixFrame frameAt(const FacePoint& reference);

}  // namespace strata::healpix
