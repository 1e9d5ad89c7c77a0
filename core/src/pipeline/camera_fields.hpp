#pragma once
#include <array>

#include <strata/camera.hpp>

#include "pipeline/interval.hpp"

namespace strata::loader {

// A number of the camera as pipelines (`camera:`) and camera paths (keyframes, `from:` and `to:`) write it.
struct CameraField {
  const char* name;
  double Camera::*member;
  Interval allowed;
  const char* units;
};

// The field of view's bounds, deg. A 2 cm checkerboard seen from 1 km through 1024 pixels is crisp down to
// 1e-4 degrees and at 1e-5 blurred and 100 pixels out of place: longitude and latitude reach the GPU relative
// to the point below the eye, in float, which resolves about 1e-6 of the distance. 1e-3 keeps ten times that
// room (at 1e-8 the surface tore, at 1e-320 the projection overflowed and drew nothing) and still frames
// Mars seen from Earth (about 6e-3 degrees across). Up to 179: at 180 the projection is singular.
inline constexpr double kLeastFieldOfView = 0.001, kMostFieldOfView = 179.0;

inline const std::array<CameraField, 6> kCameraFields{{
    {"lon", &Camera::lon, Interval::any(), "deg"},
    {"lat", &Camera::lat, Interval::closed(-90.0, 90.0), "deg"},
    {"altitude", &Camera::altitude, Interval::above(0.0), "m"},
    {"heading", &Camera::heading, Interval::any(), "deg"},
    {"tilt", &Camera::tilt, Interval::closed(0.0, 90.0), "deg"},
    {"fov", &Camera::fov, Interval::closed(kLeastFieldOfView, kMostFieldOfView), "deg"},
}};

}  // namespace strata::loader
