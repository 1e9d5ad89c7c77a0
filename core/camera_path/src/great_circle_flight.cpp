// A flight from one camera to another along the great circle between the points below them, zooming out and
// back in along van Wijk and Nuij's optimal path (zoom_pan_curve.hpp), travelled at constant speed in time.
// Their u runs along the great circle (m on the body) and their w is the ground height of the view looking
// straight down, 2 altitude tan(fov / 2). Heading, tilt and field of view ease from the first camera's to the
// last's (smoothstep), heading the shorter way, and the tilt turns toward straight down while the view is
// zoomed out.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_motion.hpp"
#include "monotone_cubic.hpp"
#include "sphere_geodesics.hpp"
#include "zoom_pan_curve.hpp"

namespace strata::paths {
namespace {

double viewWidth(const Camera& camera) {
  return 2.0 * camera.altitude * std::tan(camera.fov * std::numbers::pi / 360.0);
}

double ease(double from, double to, double fraction) { return hermite(from, 0.0, to, 0.0, fraction); }

class GreatCircleFlight final : public CameraPath::Motion {
 public:
  GreatCircleFlight(const CameraFlight& flight, double radius)
      : flight_(flight),
        from_(unitVectorDegrees(flight.from.lon, flight.from.lat)),
        to_(unitVectorDegrees(flight.to.lon, flight.to.lat)),
        distance_(radius * arcAngle(from_, to_)),
        curve_(distance_, viewWidth(flight.from), viewWidth(flight.to), flight.rho) {}

  // Their model sees the ground from straight above. A tilted view zoomed out would look past the planet,
  // so the tilt shrinks toward 0 (straight down) by the factor the view is wider than a flight without the
  // zoom-out, whose width goes geometrically from one end's to the other's; at both ends the factor is 1.
  double nadirFactor(double fraction, double width) const {
    const double first = curve_.width(0.0), last = curve_.width(curve_.length());
    const double direct = std::pow(first, 1.0 - fraction) * std::pow(last, fraction);
    return std::min(1.0, direct / width);
  }

  double start() const override { return 0.0; }
  double end() const override { return flight_.duration; }

  Camera at(double time) const override {
    const double fraction = time / flight_.duration;
    const double s = curve_.length() * fraction;
    const glm::dvec2 lonLat =
        lonLatDegrees(curve_.pans() ? slerp(from_, to_, std::clamp(curve_.ground(s) / distance_, 0.0, 1.0)) : from_);
    Camera camera;
    camera.lon = lonLat.x;
    camera.lat = lonLat.y;
    camera.heading =
        wrapHeading(ease(flight_.from.heading, nearestHeading(flight_.from.heading, flight_.to.heading), fraction));
    camera.tilt = ease(flight_.from.tilt, flight_.to.tilt, fraction) * nadirFactor(fraction, curve_.width(s));
    camera.fov = ease(flight_.from.fov, flight_.to.fov, fraction);
    camera.altitude = curve_.width(s) / (2.0 * std::tan(camera.fov * std::numbers::pi / 360.0));
    return camera;
  }

 private:
  CameraFlight flight_;
  glm::dvec3 from_, to_;
  double distance_;  // m along the ground
  ZoomPanCurve curve_;
};

}  // namespace

std::shared_ptr<const CameraPath::Motion> makeGreatCircleFlight(const CameraFlight& flight, double radius) {
  return std::make_shared<GreatCircleFlight>(flight, radius);
}

}  // namespace strata::paths
