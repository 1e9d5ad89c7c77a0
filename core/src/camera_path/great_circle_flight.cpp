// A flight from one camera to another along the great circle between the points below them, zooming out and
// back in: the optimal path of van Wijk and Nuij 2003, "Smooth and efficient zooming and panning" (IEEE
// InfoVis), sections 3 and 4. Their flat-world model measures u, the distance along the ground, and w, the
// width of the view, in one unit; the path in (u, w) minimises the perceived motion, and travelling its
// length S at constant speed gives a constant perceived speed. Here u runs along the great circle (m on
// the body) and w is the ground height of the view looking straight down, 2 altitude tan(fov / 2). Heading,
// tilt and field of view ease from the first camera's to the last's (smoothstep), heading the shorter way,
// and the tilt turns toward straight down while the view is zoomed out.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_path/camera_motion.hpp"
#include "camera_path/monotone_cubic.hpp"
#include "camera_path/sphere_geodesics.hpp"

namespace strata::paths {
namespace {

// Below this ground distance (m) the flight is a pure zoom (their equation 11, the limit u1 -> 0).
constexpr double kSameGround = 1e-6;

double viewWidth(const Camera& camera) {
  return 2.0 * camera.altitude * std::tan(camera.fov * std::numbers::pi / 360.0);
}

// The (u, w) path of van Wijk and Nuij from (0, w0) to (u1, w1), by arc length s from 0 to length().
class ZoomPanCurve {
 public:
  ZoomPanCurve(double u1, double w0, double w1, double rho) : u1_(u1), w0_(w0), w1_(w1), rho_(rho) {
    if (u1 < kSameGround) {
      length_ = std::abs(std::log(w1 / w0)) / rho;
      return;
    }
    const double rho2 = rho * rho, rho4 = rho2 * rho2;
    const double b0 = (w1 * w1 - w0 * w0 + rho4 * u1 * u1) / (2.0 * w0 * rho2 * u1);
    const double b1 = (w1 * w1 - w0 * w0 - rho4 * u1 * u1) / (2.0 * w1 * rho2 * u1);
    // r = ln(-b + sqrt(b^2 + 1)) = -asinh(b), without the cancellation of the first form for large b.
    r0_ = -std::asinh(b0);
    length_ = (-std::asinh(b1) - r0_) / rho;
  }

  double length() const { return length_; }

  double ground(double s) const {  // u(s), their equation 9
    if (u1_ < kSameGround) return 0.0;
    return w0_ / (rho_ * rho_) * (std::cosh(r0_) * std::tanh(rho_ * s + r0_) - std::sinh(r0_));
  }

  double width(double s) const {  // w(s)
    if (u1_ < kSameGround) return w0_ * std::exp((w1_ < w0_ ? -1.0 : 1.0) * rho_ * s);
    return w0_ * std::cosh(r0_) / std::cosh(rho_ * s + r0_);
  }

 private:
  double u1_, w0_, w1_, rho_;
  double r0_ = 0.0;
  double length_ = 0.0;
};

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
    const glm::dvec2 lonLat = lonLatDegrees(
        distance_ < kSameGround ? from_ : slerp(from_, to_, std::clamp(curve_.ground(s) / distance_, 0.0, 1.0)));
    Camera camera;
    camera.lon = lonLat.x;
    camera.lat = lonLat.y;
    camera.heading = wrapHeading(ease(flight_.from.heading, nearestHeading(flight_.from.heading, flight_.to.heading),
                                      fraction));
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
