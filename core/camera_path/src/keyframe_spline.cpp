// Keyframes joined by a C1 spline in double precision. The point below the camera follows a spherical
// Catmull-Rom spline: each segment is a cubic Bezier curve on the sphere evaluated by de Casteljau's
// construction with slerp (Shoemake 1985, "Animating rotation with quaternion curves", SIGGRAPH), its inner
// control points set a third of a segment along the tangents, so the velocity is continuous across
// keyframes. Keyframes on one great circle give a track on that great circle. Altitude is interpolated in log
// space (its speed scales with the altitude, from 100,000 km to a metre), heading the shorter way round, and
// these, tilt and field of view by monotone cubics that never overshoot a keyframe. The path starts and ends
// at rest.
#include <algorithm>
#include <cmath>
#include <utility>

#include "camera_motion.hpp"
#include "monotone_cubic.hpp"
#include "sphere_geodesics.hpp"

namespace strata::paths {
namespace {

// The tangent velocity (rad/s) of the track at each keyframe: Catmull-Rom's mean of the velocities toward
// the neighbours, for keyframes unevenly spaced in time; zero at the ends.
std::vector<glm::dvec3> trackVelocities(const std::vector<glm::dvec3>& points, const std::vector<double>& times) {
  std::vector<glm::dvec3> velocities(points.size(), glm::dvec3(0.0));
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    const glm::dvec3 ahead = logarithm(points[k], points[k + 1]) / (times[k + 1] - times[k]);
    const glm::dvec3 behind = -logarithm(points[k], points[k - 1]) / (times[k] - times[k - 1]);
    velocities[k] = 0.5 * (ahead + behind);
  }
  return velocities;
}

std::vector<double> fieldOf(const std::vector<CameraKeyframe>& keyframes, double (*field)(const Camera&)) {
  std::vector<double> values;
  for (const auto& keyframe : keyframes) values.push_back(field(keyframe.camera));
  return values;
}

// Headings rewritten so that each differs from the one before by at most half a turn.
std::vector<double> unwrappedHeadings(const std::vector<CameraKeyframe>& keyframes) {
  std::vector<double> headings{keyframes.front().camera.heading};
  for (std::size_t k = 1; k < keyframes.size(); ++k)
    headings.push_back(nearestHeading(headings.back(), keyframes[k].camera.heading));
  return headings;
}

std::vector<double> timesOf(const std::vector<CameraKeyframe>& keyframes) {
  std::vector<double> times;
  for (const auto& keyframe : keyframes) times.push_back(keyframe.time);
  return times;
}

std::vector<glm::dvec3> trackPoints(const std::vector<CameraKeyframe>& keyframes) {
  std::vector<glm::dvec3> points;
  for (const auto& keyframe : keyframes) points.push_back(unitVectorDegrees(keyframe.camera.lon, keyframe.camera.lat));
  return points;
}

class KeyframeSpline final : public CameraPath::Motion {
 public:
  explicit KeyframeSpline(const std::vector<CameraKeyframe>& keyframes)
      : times_(timesOf(keyframes)),
        points_(trackPoints(keyframes)),
        velocities_(trackVelocities(points_, times_)),
        logAltitude_(times_, fieldOf(keyframes, [](const Camera& c) { return std::log(c.altitude); })),
        heading_(times_, unwrappedHeadings(keyframes)),
        tilt_(times_, fieldOf(keyframes, [](const Camera& c) { return c.tilt; })),
        fov_(times_, fieldOf(keyframes, [](const Camera& c) { return c.fov; })) {}

  double start() const override { return times_.front(); }
  double end() const override { return times_.back(); }

  Camera at(double time) const override {
    const std::size_t segment = segmentAt(time);
    const glm::dvec2 lonLat = lonLatDegrees(trackAt(segment, time));
    Camera camera;
    camera.lon = lonLat.x;
    camera.lat = lonLat.y;
    camera.altitude = std::exp(logAltitude_.at(segment, time));
    camera.heading = wrapHeading(heading_.at(segment, time));
    camera.tilt = tilt_.at(segment, time);
    camera.fov = fov_.at(segment, time);
    return camera;
  }

 private:
  // The last segment whose start is at or before `time`.
  std::size_t segmentAt(double time) const {
    const auto after = std::upper_bound(times_.begin() + 1, times_.end() - 1, time);
    return std::size_t(after - times_.begin()) - 1;
  }

  // De Casteljau's construction on the sphere over the segment's four control points.
  glm::dvec3 trackAt(std::size_t segment, double time) const {
    const double h = times_[segment + 1] - times_[segment];
    const double u = (time - times_[segment]) / h;
    const glm::dvec3 b0 = points_[segment], b3 = points_[segment + 1];
    const glm::dvec3 b1 = exponential(b0, velocities_[segment] * (h / 3.0));
    const glm::dvec3 b2 = exponential(b3, -velocities_[segment + 1] * (h / 3.0));
    const glm::dvec3 c0 = slerp(b0, b1, u), c1 = slerp(b1, b2, u), c2 = slerp(b2, b3, u);
    return slerp(slerp(c0, c1, u), slerp(c1, c2, u), u);
  }

  std::vector<double> times_;
  std::vector<glm::dvec3> points_;
  std::vector<glm::dvec3> velocities_;
  MonotoneCubic logAltitude_, heading_, tilt_, fov_;
};

}  // namespace

std::shared_ptr<const CameraPath::Motion> makeKeyframeSpline(std::vector<CameraKeyframe> keyframes) {
  return std::make_shared<KeyframeSpline>(keyframes);
}

}  // namespace strata::paths
