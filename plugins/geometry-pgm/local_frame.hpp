#pragma once
#include <glm/glm.hpp>

namespace strata::pgm {

// The east-north-up frame at the point below the eye, View::reference (longitude and latitude, rad, in
// Strata's planet-fixed axes: +z north, +x at longitude 0): the rotation from planet-fixed axes to it, with
// rows east, north and up. The GPU casts the grid in this frame, where the nadir is exactly (0, 0, -1):
// the nadir rounded to float in any other frame would move the planet's centre sideways by up to 0.4 m
// under an Earth-sized view, and by a different amount each frame (digest 003 section 1.8). It also gives
// each point's longitude and latitude from the reference without cancellation (pgm_local_frame.glsl).
glm::dmat3 planetToLocal(glm::dvec2 reference);

}  // namespace strata::pgm
