#pragma once
#include <strata/host/camera_path.hpp>

namespace strata::cli {

// `strata render --path FILE --frames N`: N frames evenly spaced in time along a camera path, the first at its
// start and the last at its end, so that played at framesPerSecond() the sequence lasts as long as the path.
struct PathFrames {
  int count = 0;
  double duration = 0.0;  // s

  double fractionOf(int frame) const { return double(frame) / double(count - 1); }
  double framesPerSecond() const { return double(count - 1) / duration; }
};

// Frames a second when --frames is not given: video's common rate.
inline constexpr double kDefaultFramesPerSecond = 30.0;

// `requested` frames (--frames; 0 when not given: kDefaultFramesPerSecond of the path's time); throws
// strata::Error naming --frames when fewer than 2.
PathFrames pathFrames(const CameraPath& path, int requested);

}  // namespace strata::cli
