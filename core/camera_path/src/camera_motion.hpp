#pragma once
#include <memory>
#include <vector>

#include <strata/host/camera_path.hpp>

namespace strata {

// One kind of camera path: the camera at each moment from start() to end() (CameraPath clamps outside).
class CameraPath::Motion {
 public:
  virtual ~Motion() = default;
  virtual double start() const = 0;
  virtual double end() const = 0;
  virtual Camera at(double time) const = 0;
};

namespace paths {

// Keyframes joined by a spline (keyframe_spline.cpp); preconditions as CameraPath::throughKeyframes.
std::shared_ptr<const CameraPath::Motion> makeKeyframeSpline(std::vector<CameraKeyframe> keyframes);
// A great-circle flight (great_circle_flight.cpp) over a sphere of `radius` (m).
std::shared_ptr<const CameraPath::Motion> makeGreatCircleFlight(const CameraFlight& flight, double radius);

// The heading `to` written as the one nearest `from`, so that a turn takes the shorter way round:
// from 350, 10 becomes 370. A half turn goes clockwise.
double nearestHeading(double from, double to);
// A heading in [0, 360).
double wrapHeading(double heading);

}  // namespace paths
}  // namespace strata
