#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "camera_motion.hpp"
#include "sphere_geodesics.hpp"

namespace strata {
namespace {

void requireKeyframes(const std::vector<CameraKeyframe>& keyframes) {
  if (keyframes.size() < 2) throw std::invalid_argument("a camera path needs at least two keyframes");
  for (std::size_t k = 1; k < keyframes.size(); ++k) {
    const Camera &before = keyframes[k - 1].camera, &after = keyframes[k].camera;
    if (!(keyframes[k].time > keyframes[k - 1].time))
      throw std::invalid_argument("keyframe " + std::to_string(k + 1) + " is not later than the one before");
    if (paths::antipodal(paths::unitVectorDegrees(before.lon, before.lat),
                         paths::unitVectorDegrees(after.lon, after.lat)))
      throw std::invalid_argument("keyframes " + std::to_string(k) + " and " + std::to_string(k + 1) +
                                  " are antipodal: no one great circle joins them");
  }
}

}  // namespace

CameraPath::CameraPath(std::shared_ptr<const Motion> motion) : motion_(std::move(motion)) {}

CameraPath CameraPath::throughKeyframes(std::vector<CameraKeyframe> keyframes) {
  requireKeyframes(keyframes);
  return CameraPath(paths::makeKeyframeSpline(std::move(keyframes)));
}

CameraPath CameraPath::flight(const CameraFlight& flight, const Body& body) {
  if (!(flight.duration > 0.0)) throw std::invalid_argument("a flight's duration must be positive");
  if (!(flight.rho > 0.0)) throw std::invalid_argument("a flight's rho must be positive");
  if (paths::antipodal(paths::unitVectorDegrees(flight.from.lon, flight.from.lat),
                       paths::unitVectorDegrees(flight.to.lon, flight.to.lat)))
    throw std::invalid_argument("a flight between antipodal points has no one great circle");
  return CameraPath(paths::makeGreatCircleFlight(flight, body.radius));
}

double CameraPath::start() const { return motion_->start(); }
double CameraPath::end() const { return motion_->end(); }

Camera CameraPath::at(double time) const { return motion_->at(std::clamp(time, start(), end())); }

Camera CameraPath::atFraction(double fraction) const {
  return at(start() + (end() - start()) * std::clamp(fraction, 0.0, 1.0));
}

}  // namespace strata
