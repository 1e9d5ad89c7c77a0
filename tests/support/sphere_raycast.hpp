#pragma once
#include <optional>

#include <strata/camera.hpp>

namespace strata::test {

// Where the ray through the centre of pixel (x, y) (origin at the top left, as images are read) meets a
// sphere of `radius` about the planet's centre, computed in double: the reference rendered images are
// compared with.
struct SurfaceHit {
  double lon;        // deg in [-180, 180)
  double lat;        // deg
  double incidence;  // cosine of the angle between the ray and the surface normal (1: head-on)
};

std::optional<SurfaceHit> raycastSphere(const View& view, double radius, double x, double y);

// The expected radius in pixels of a sphere of `radius` seen from distance `distance` to its centre.
double discRadiusPixels(const View& view, double radius, double distance);

}  // namespace strata::test
