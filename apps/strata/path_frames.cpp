#include "path_frames.hpp"

#include <cmath>
#include <string>

#include <strata/error.hpp>

namespace strata::cli {

PathFrames pathFrames(const CameraPath& path, int requested) {
  const double duration = path.end() - path.start();
  const int count = requested != 0 ? requested : int(std::lround(duration * kDefaultFramesPerSecond)) + 1;
  if (count < 2)
    throw Error(SourceLocation{"--frames"}, "a camera path takes at least 2 frames, got " + std::to_string(count),
                "give --frames N with N >= 2, e.g. --frames " +
                    std::to_string(int(std::lround(duration * kDefaultFramesPerSecond)) + 1) +
                    " for 30 frames a second of the path");
  return {count, duration};
}

}  // namespace strata::cli
