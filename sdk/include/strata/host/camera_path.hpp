#pragma once
#include <filesystem>
#include <memory>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/body.hpp>
#include <strata/camera.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// A camera at a moment of a path, in seconds from the path's own zero.
struct CameraKeyframe {
  double time = 0.0;  // s
  Camera camera;
};

// A great-circle flight from one camera to another (van Wijk and Nuij 2003): the ground track follows the
// great circle, and the view zooms out and back in so that the perceived speed stays constant.
struct CameraFlight {
  Camera from;
  Camera to;
  double duration = 10.0;  // s
  // The trade-off between zooming and panning of van Wijk and Nuij: their user study preferred
  // about sqrt(2); larger values zoom out further before panning.
  double rho = 1.42;
};

// Where the camera is at every moment of an animation: keyframes joined by a smooth spline, or a great-circle
// flight. Evaluated in double precision; `strata render --path` and `strata bench` step along it
// (docs/camera-paths.md).
class CameraPath {
 public:
  // Keyframes in increasing time, at least two, no two sub-camera points antipodal; throws
  // std::invalid_argument otherwise (readCameraPath gives users located errors before this).
  static CameraPath throughKeyframes(std::vector<CameraKeyframe> keyframes);
  // A flight over a body of `body.radius`; throws std::invalid_argument for a duration <= 0 or rho <= 0.
  static CameraPath flight(const CameraFlight& flight, const Body& body);

  double start() const;  // s
  double end() const;    // s
  // The camera at `time` (s); before start() it is the first camera, after end() the last.
  Camera at(double time) const;
  // The camera at a fraction of the path's duration: 0 at start(), 1 at end().
  Camera atFraction(double fraction) const;

  class Motion;  // how a path moves: one implementation per kind of path

 private:
  explicit CameraPath(std::shared_ptr<const Motion> motion);
  std::shared_ptr<const Motion> motion_;
};

// Reads a path file (format `strata-path: 1`, docs/camera-paths.md). A flight is measured over `body`, the
// pipeline's. Throws strata::Error naming the file, line and column and what would fix it.
CameraPath readCameraPath(const std::filesystem::path& file, const Body& body);
// The same from text, reported as `fileName`.
CameraPath parseCameraPath(const std::string& text, const std::filesystem::path& fileName, const Body& body);

}  // namespace strata
STRATA_EXPORTS_END
