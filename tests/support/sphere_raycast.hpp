#pragma once
#include <functional>
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
  double distance;   // m from the eye along the ray
};

std::optional<SurfaceHit> raycastSphere(const View& view, double radius, double x, double y);

// Where that ray first meets the terrain radius + height(lon, lat) (m, degrees), which lies at most `highest`
// above the sphere: marched in steps of `step` m from where it enters that height, then bisected to a
// millimetre. `radiusAt` receives the hit's distance from the planet's centre. For terrain whose heights
// change by no more than `step` times its steepest slope within a step (steps, walls) the first crossing is
// found.
std::optional<SurfaceHit> raycastTerrain(const View& view, double radius,
                                         const std::function<double(double lon, double lat)>& height, double highest,
                                         double step, double x, double y, double* radiusAt = nullptr);

// The distance from the eye along the ray through the centre of pixel (x, y) of a reversed depth read back
// from a geometry's buffer (strata/plugin/output.hpp, readDepth); infinity where it is 0 (nothing drawn).
double rayDistance(const View& view, float depth, double x, double y);

// The expected radius in pixels of a sphere of `radius` seen from distance `distance` to its centre.
double discRadiusPixels(const View& view, double radius, double distance);

}  // namespace strata::test
